/* SPDX-License-Identifier: MIT */
#include "mesh_io.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int push(agjk_vec3 **v, int *n, int *cap, double x, double y, double z) {
    if (*n == *cap) {
        int nc = *cap ? 2 * *cap : 256;
        agjk_vec3 *nv = realloc(*v, (size_t)nc * sizeof *nv);
        if (!nv) return -1;
        *v = nv;
        *cap = nc;
    }
    (*v)[*n].x = x;
    (*v)[*n].y = y;
    (*v)[*n].z = z;
    ++*n;
    return 0;
}

static int ends_with(const char *s, const char *suffix) {
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

static int read_obj(FILE *f, agjk_vec3 **v, int *n, int *cap) {
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        double x, y, z;
        if (line[0] == 'v' && (line[1] == ' ' || line[1] == '\t') &&
            sscanf(line + 2, "%lf %lf %lf", &x, &y, &z) == 3)
            if (push(v, n, cap, x, y, z) != 0) return -1;
    }
    return 0;
}

/* OFF: "OFF", then "nv nf ne" (comments with #), then nv vertex lines. */
static int read_off(FILE *f, agjk_vec3 **v, int *n, int *cap) {
    char line[1024];
    int nv = -1, i = 0, header = 0;
    while (fgets(line, sizeof line, f)) {
        char *s = line;
        double x, y, z;
        while (*s == ' ' || *s == '\t') ++s;
        if (*s == '#' || *s == '\n' || *s == '\0') continue;
        if (!header) {
            header = 1;
            if (strncmp(s, "OFF", 3) == 0) {
                s += 3;
                if (sscanf(s, "%d", &nv) == 1) continue;
                continue;
            }
        }
        if (nv < 0) {
            if (sscanf(s, "%d", &nv) != 1) return -1;
            continue;
        }
        if (i >= nv) break;
        if (sscanf(s, "%lf %lf %lf", &x, &y, &z) != 3) return -1;
        if (push(v, n, cap, x, y, z) != 0) return -1;
        ++i;
    }
    return nv >= 0 && i == nv ? 0 : -1;
}

int bench_read_mesh_file(const char *path, agjk_vec3 **vertices) {
    FILE *f = fopen(path, "r");
    int n = 0, cap = 0, rc;
    *vertices = NULL;
    if (!f) return -1;
    rc = ends_with(path, ".off") || ends_with(path, ".OFF") ? read_off(f, vertices, &n, &cap)
                                                            : read_obj(f, vertices, &n, &cap);
    fclose(f);
    if (rc != 0) {
        free(*vertices);
        *vertices = NULL;
        return -1;
    }
    return n;
}

static int cmp_str(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Collects mesh paths under dir, descending `depth` more levels. */
static void collect(const char *dir, int depth, char ***paths, int *n, int *cap) {
    DIR *d = opendir(dir);
    struct dirent *e;
    if (!d) return;
    while ((e = readdir(d)) != NULL) {
        char *path;
        struct stat st;
        size_t len;
        if (e->d_name[0] == '.') continue;
        len = strlen(dir) + strlen(e->d_name) + 2;
        path = malloc(len);
        if (!path) break;
        snprintf(path, len, "%s/%s", dir, e->d_name);
        if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
            if (depth > 0) collect(path, depth - 1, paths, n, cap);
            free(path);
        } else if (ends_with(path, ".obj") || ends_with(path, ".off") ||
                   ends_with(path, ".OBJ") || ends_with(path, ".OFF")) {
            if (*n == *cap) {
                int nc = *cap ? 2 * *cap : 64;
                char **np = realloc(*paths, (size_t)nc * sizeof *np);
                if (!np) { free(path); break; }
                *paths = np;
                *cap = nc;
            }
            (*paths)[(*n)++] = path;
        } else {
            free(path);
        }
    }
    closedir(d);
}

int bench_read_mesh_dir(const char *dir, bench_mesh_source *out, int max_meshes, double scale) {
    char **paths = NULL;
    int n = 0, cap = 0, i;
    DIR *probe = opendir(dir);
    memset(out, 0, sizeof *out);
    if (!probe) return -1;
    closedir(probe);
    collect(dir, 1, &paths, &n, &cap);
    if (n > 1) qsort(paths, (size_t)n, sizeof *paths, cmp_str);
    out->vertices = calloc((size_t)(n ? n : 1), sizeof *out->vertices);
    out->counts = calloc((size_t)(n ? n : 1), sizeof *out->counts);
    if (!out->vertices || !out->counts) exit(2);
    for (i = 0; i < n; ++i) {
        agjk_vec3 *v = NULL, lo, hi, c;
        int count = out->count < max_meshes ? bench_read_mesh_file(paths[i], &v) : -2, j, bad = 0;
        if (count == -2) { free(paths[i]); continue; }
        if (count < 4) {
            fprintf(stderr, "agjk-bench: warning: skipping %s (%s)\n", paths[i],
                    count < 0 ? "unreadable" : "fewer than 4 vertices");
            free(v);
            free(paths[i]);
            continue;
        }
        lo = hi = v[0];
        for (j = 0; j < count; ++j) {
            if (!isfinite(v[j].x) || !isfinite(v[j].y) || !isfinite(v[j].z)) { bad = 1; break; }
            lo.x = fmin(lo.x, v[j].x); lo.y = fmin(lo.y, v[j].y); lo.z = fmin(lo.z, v[j].z);
            hi.x = fmax(hi.x, v[j].x); hi.y = fmax(hi.y, v[j].y); hi.z = fmax(hi.z, v[j].z);
        }
        if (bad) {
            fprintf(stderr, "agjk-bench: warning: skipping %s (non-finite vertex %d)\n",
                    paths[i], j);
            free(v);
            free(paths[i]);
            continue;
        }
        c.x = 0.5 * (lo.x + hi.x);
        c.y = 0.5 * (lo.y + hi.y);
        c.z = 0.5 * (lo.z + hi.z);
        for (j = 0; j < count; ++j) {
            v[j].x = (v[j].x - c.x) * scale;
            v[j].y = (v[j].y - c.y) * scale;
            v[j].z = (v[j].z - c.z) * scale;
        }
        out->vertices[out->count] = v;
        out->counts[out->count] = count;
        out->count++;
        free(paths[i]);
    }
    free(paths);
    return out->count;
}

void bench_free_meshes(bench_mesh_source *m) {
    int i;
    for (i = 0; i < m->count; ++i) free(m->vertices[i]);
    free(m->vertices);
    free(m->counts);
    memset(m, 0, sizeof *m);
}
