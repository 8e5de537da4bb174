/* servo-bc: the embedded runner.
 *   servo-bc SCRIPT              runs the script
 *   servo-bc --check SCRIPT      checks every command of the script, runs and writes nothing
 *   servo-bc --decks DIR SCRIPT  writes the script's case for every host into DIR
 *   servo-bc --version           prints the version
 *   servo-bc --columns           prints the results file's columns (columns.h) as a Markdown table
 *   servo-bc --keywords          prints the servo_bc keywords (keywords.h) as a Markdown table */
#define _POSIX_C_SOURCE 200809L
#include "decks.h"
#include "sbc/columns.h"
#include "sbc/keywords.h"
#include "sbc/embedded/script.h"
#include "sbc/version.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

static const char usage[] =
    "usage: servo-bc SCRIPT              run the script (docs/runner.md)\n"
    "       servo-bc --check SCRIPT      check every command of the script; run and write nothing\n"
    "       servo-bc --decks DIR SCRIPT  write the script's case for every host into DIR\n"
    "       servo-bc --version           print the version (CHANGELOG.md)\n"
    "       servo-bc --columns           print the results file's columns as a Markdown table\n"
    "       servo-bc --keywords          print the servo_bc keywords as a Markdown table\n";

/* the columns of the results file (columns.h), as docs/servo_bc.md shows them */
static void print_keywords(void)
{
    int k;
    puts("| keyword | values | meaning | default |");
    puts("| --- | --- | --- | --- |");
    for (k = 0; k < SBC_KEYWORDS; ++k) {
        const char *p = sbc_keywords[k].names;
        fputs("| ", stdout);
        while (*p) { /* each name in backquotes */
            const size_t n = strcspn(p, " ");
            printf("`%.*s`%s", (int)n, p, p[n] ? " " : "");
            p += n + (p[n] == ' ');
        }
        printf(" | %s | %s | %s |\n", sbc_keywords[k].values, sbc_keywords[k].meaning, sbc_keywords[k].fallback);
    }
}

static void print_columns(void)
{
    static const char *const written[] = {"count", "17 digits", "6 digits"}; /* by sbc_column_format */
    int k;
    puts("| column | in | unit | written as | meaning |");
    puts("| --- | --- | --- | --- | --- |");
    for (k = 0; k < SBC_COLUMNS; ++k) {
        const sbc_column *c = &sbc_columns[k];
        printf("| `%s` | %s | %s | %s | %s |\n", c->name, c->dimensions & SBC_COLUMN_2D ? "2D, 3D" : "3D", c->unit,
               written[c->format], c->description);
    }
}

int main(int argc, char **argv)
{
    sbc_error err;
    sbc_status st;
    /* past the file size limit a write fails with a message naming the file
       (results.h), instead of SIGXFSZ ending the process without one */
    signal(SIGXFSZ, SIG_IGN);
    if (argc == 2 && (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0)) {
        fputs(usage, stdout);
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--version") == 0) {
        printf("servo-bc %s\n", sbc_version());
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--columns") == 0) {
        print_columns();
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--keywords") == 0) {
        print_keywords();
        return 0;
    }
    if (argc == 2 && argv[1][0] != '-')
        st = sbc_script_run_file(argv[1], stdout, &err);
    else if (argc == 3 && strcmp(argv[1], "--check") == 0)
        st = sbc_script_check_file(argv[2], stdout, &err);
    else if (argc == 4 && strcmp(argv[1], "--decks") == 0)
        st = sbc_script_decks_file(argv[3], argv[2], sbc_runner_write_decks, stdout, &err);
    else {
        fprintf(stderr, "ERROR: servo-bc: %s%s%s\n%s", argc < 2 ? "no script" : "unknown arguments starting at '",
                argc < 2 ? "" : argv[1], argc < 2 ? "" : "'", usage);
        return 2;
    }
    if (st != SBC_OK) {
        fflush(stdout);
        fprintf(stderr, "ERROR: %s\n", err.message);
        return 1;
    }
    if (argc == 3)
        printf("check: %s is ready to run\n", argv[2]);
    return 0;
}
