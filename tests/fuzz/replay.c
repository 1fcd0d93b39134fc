/* SPDX-License-Identifier: MIT */
/* Replays fuzz inputs without libFuzzer: every file named on the command line,
 * or every file of the directories named (default: FUZZ_DEFAULT_DIR, set by
 * the build), goes once through LLVMFuzzerTestOneInput. A violated invariant
 * aborts, so `make check` fails on any regression. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_file(const char *path) {
    FILE *f = fopen(path, "rb");
    uint8_t *buf;
    long n;
    if (!f) { perror(path); return 1; }
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return 1;
    }
    buf = malloc(n > 0 ? (size_t)n : 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n) { fclose(f); free(buf); return 1; }
    fclose(f);
    LLVMFuzzerTestOneInput(buf, (size_t)n);
    free(buf);
    return 0;
}

static int replay_path(const char *path, int *count) {
    struct stat st;
    if (stat(path, &st) != 0) { perror(path); return 1; }
    if (!S_ISDIR(st.st_mode)) { ++*count; return replay_file(path); }
    DIR *d = opendir(path);
    struct dirent *e;
    int bad = 0;
    if (!d) { perror(path); return 1; }
    while ((e = readdir(d)) != NULL) {
        char full[4096];
        if (e->d_name[0] == '.') continue;
        snprintf(full, sizeof full, "%s/%s", path, e->d_name);
        bad |= replay_path(full, count);
    }
    closedir(d);
    return bad;
}

int main(int argc, char **argv) {
    int bad = 0, count = 0;
    if (argc < 2) {
#ifdef FUZZ_DEFAULT_DIR
        bad = replay_path(FUZZ_DEFAULT_DIR, &count);
#else
        fprintf(stderr, "usage: %s FILE-OR-DIR...\n", argv[0]);
        return 2;
#endif
    }
    for (int i = 1; i < argc; i++) bad |= replay_path(argv[i], &count);
    printf("replayed %d fuzz inputs%s\n", count, bad ? " (some unreadable)" : "");
    return bad;
}
