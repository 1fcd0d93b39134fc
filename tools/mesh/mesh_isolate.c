/* SPDX-License-Identifier: MIT */
/* Runs the assimp import in a child process, so that a crash inside assimp on
 * a malformed file is reported as an error instead of killing the caller.
 * OFF and OBJ files are read by our own reader (mesh_text.c), in this
 * process: it needs no such guard, and the points need no copy through a pipe.
 *
 * Fuzzing showed assimp 5.2 reading out of bounds (SIGSEGV) on OFF files with
 * more vertex lines than declared and on PLY files whose faces index missing
 * vertices; we cannot fix assimp, so we contain it. The child loads the file
 * with mesh_load_in_process() and sends the result through a pipe: a fixed
 * header (status, counts, message), then the points as raw doubles (same
 * machine, same ABI). The parent reads until EOF, then reaps the child; a
 * child killed by a signal means the importer crashed.
 *
 * assimp can also loop forever on a malformed file (fuzzing: a 245-byte PLY
 * whose header never ends). The child therefore gets a time budget that grows
 * with the file size, far above what assimp needs on valid files (it reads
 * text meshes at 5 MB/s and more on a loaded machine), and dies by SIGALRM
 * (default action) when it runs out. alarm() timers are not inherited across
 * fork(), so the caller's remaining time, if shorter, is passed on the same
 * way. The child inherits the address-space limit. */
#include "mesh.h"

#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* Import time budget: a base plus this many seconds per megabyte. */
#define IMPORT_BASE_SECONDS 10.0
#define IMPORT_SECONDS_PER_MB 1.0

static unsigned import_budget(const char *path) {
    struct stat st;
    double mb = stat(path, &st) == 0 ? (double)st.st_size / (1024.0 * 1024.0) : 0.0;
    double s = IMPORT_BASE_SECONDS + IMPORT_SECONDS_PER_MB * mb;
    return s > 1e6 ? 1000000u : (unsigned)s;
}

typedef struct wire_header {
    int32_t ok;
    int32_t double_precision;
    uint64_t count, mesh_count, face_count;
    char format[16];
    char precision_note[64];
    char err[MESH_ERROR_SIZE];
} wire_header;

static int write_all(int fd, const void *buf, size_t len) {
    const char *p = buf;
    while (len > 0) {
        ssize_t n = write(fd, p, len);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return 0;
        p += n;
        len -= (size_t)n;
    }
    return 1;
}

/* Reads exactly len bytes; 0 on EOF or error before that. */
static int read_all(int fd, void *buf, size_t len) {
    char *p = buf;
    while (len > 0) {
        ssize_t n = read(fd, p, len);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return 0;
        p += n;
        len -= (size_t)n;
    }
    return 1;
}

static void run_child(const char *path, int fd, unsigned seconds_left) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGALRM, &sa, NULL); /* not the parent's handler: just die */
    if (seconds_left) alarm(seconds_left);
    mesh_points pts;
    wire_header h;
    memset(&h, 0, sizeof h);
    h.ok = mesh_load_in_process(path, &pts, h.err, sizeof h.err);
    if (h.ok) {
        h.double_precision = pts.double_precision;
        h.count = pts.count;
        h.mesh_count = pts.mesh_count;
        h.face_count = pts.face_count;
        memcpy(h.format, pts.format, sizeof h.format);
        memcpy(h.precision_note, pts.precision_note, sizeof h.precision_note);
    }
    int ok = write_all(fd, &h, sizeof h) &&
             (!h.ok || write_all(fd, pts.points, pts.count * sizeof *pts.points));
    /* _exit: no atexit handlers, no second flush of the parent's stdio buffers. */
    _exit(ok ? 0 : 1);
}

/* Reads the child's answer into `out`; 1 if complete. */
static int read_answer(int fd, mesh_points *out, char *err, size_t err_size, int *answered) {
    wire_header h;
    *answered = 0;
    if (!read_all(fd, &h, sizeof h)) return 0;
    h.err[sizeof h.err - 1] = '\0';
    h.format[sizeof h.format - 1] = '\0';
    h.precision_note[sizeof h.precision_note - 1] = '\0';
    *answered = 1;
    if (!h.ok) {
        snprintf(err, err_size, "%s", h.err);
        return 0;
    }
    if (h.count == 0 || h.count > SIZE_MAX / sizeof *out->points) return 0;
    out->points = malloc((size_t)h.count * sizeof *out->points);
    if (!out->points || !read_all(fd, out->points, (size_t)h.count * sizeof *out->points)) {
        free(out->points);
        out->points = NULL;
        *answered = 0;
        return 0;
    }
    out->count = (size_t)h.count;
    out->mesh_count = (size_t)h.mesh_count;
    out->face_count = (size_t)h.face_count;
    out->double_precision = h.double_precision;
    memcpy(out->format, h.format, sizeof out->format);
    memcpy(out->precision_note, h.precision_note, sizeof out->precision_note);
    return 1;
}

/* 1 for the formats of our own reader (by extension, as mesh_load_in_process). */
static int own_reader(const char *path) {
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    if (!dot || strlen(dot) != 4) return 0;
    char ext[4];
    for (int i = 0; i < 3; i++) ext[i] = (char)(dot[1 + i] | 0x20);
    ext[3] = '\0';
    return strcmp(ext, "off") == 0 || strcmp(ext, "obj") == 0;
}

int mesh_load(const char *path, mesh_points *out, char *err, size_t err_size) {
    const char *in_process = getenv("AGJK_MESH_IN_PROCESS");
    int fds[2];
    if (own_reader(path) || (in_process && *in_process && strcmp(in_process, "0") != 0) ||
        pipe(fds) != 0)
        return mesh_load_in_process(path, out, err, err_size);
    unsigned left = alarm(0); /* read the parent's remaining time... */
    if (left) alarm(left);    /* ...and keep it running */
    unsigned budget = import_budget(path);
    int budget_binds = !left || budget < left;
    if (budget_binds) left = budget;
    fflush(NULL);             /* nothing buffered twice */
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return mesh_load_in_process(path, out, err, err_size);
    }
    if (pid == 0) {
        close(fds[0]);
        run_child(path, fds[1], left);
    }
    close(fds[1]);
    memset(out, 0, sizeof *out);
    int answered;
    int ok = read_answer(fds[0], out, err, err_size, &answered);
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (ok) return 1;
    if (!answered) {
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM && budget_binds)
            snprintf(err, err_size,
                     "%s: the mesh importer (assimp) did not finish within %u s, far longer "
                     "than a valid file of this size needs: malformed file", path, budget);
        else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
            snprintf(err, err_size, "%s: time limit exceeded while reading the mesh", path);
        else if (WIFSIGNALED(status))
            snprintf(err, err_size,
                     "%s: the mesh importer (assimp) crashed on this file (signal %d): "
                     "malformed file", path, WTERMSIG(status));
        else
            snprintf(err, err_size, "%s: the mesh importer failed (out of memory?)", path);
    }
    mesh_points_free(out);
    return 0;
}
