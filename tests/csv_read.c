#include "csv_read.h"

#include "sbc/columns.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int csv_read(const char *path, double rows[][CSV_COLS], int max)
{
    FILE *fp = fopen(path, "r");
    char line[4096], header[4096];
    const int h = sbc_columns_header(2, header, sizeof header);
    int n = 0;
    if (!fp)
        return -1;
    if (!fgets(line, sizeof line, fp) || strncmp(line, header, (size_t)h) != 0) {
        fclose(fp);
        return -1;
    }
    while (n < max && fgets(line, sizeof line, fp)) {
        char *p = line, *end;
        int c;
        for (c = 0; c < CSV_COLS; ++c) {
            rows[n][c] = strtod(p, &end);
            if (end == p || !isfinite(rows[n][c])) {
                fclose(fp);
                return -1;
            }
            p = end + (*end == ',');
        }
        ++n;
    }
    fclose(fp);
    return n;
}

int write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    if (!fp)
        return -1;
    fputs(text, fp);
    return fclose(fp);
}
