#include "csv_read.h"

#include "sbc/columns.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the rows of a dim-dimensional file, cols numbers each */
static int read_rows(const char *path, int dim, int cols, double *rows, int max)
{
    FILE *fp = fopen(path, "r");
    char line[8192], header[8192];
    const int h = sbc_columns_header(dim, header, sizeof header);
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
        for (c = 0; c < cols; ++c) {
            double *v = &rows[(size_t)n * (size_t)cols + (size_t)c];
            *v = strtod(p, &end);
            if (end == p || !isfinite(*v)) {
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

int csv_read(const char *path, double rows[][CSV_COLS], int max) { return read_rows(path, 2, CSV_COLS, &rows[0][0], max); }

int csv_read_3d(const char *path, double rows[][SBC_COLUMNS], int max)
{
    return read_rows(path, 3, SBC_COLUMNS, &rows[0][0], max);
}

int write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    if (!fp)
        return -1;
    fputs(text, fp);
    return fclose(fp);
}
