/* SPDX-License-Identifier: MIT */
#include "guard.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

static int write_all(int fd, const void *buf, size_t n) {
    const char *p = buf;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

static void child_main(int fd, int start, int n, size_t record_size, guard_case_fn fn,
                       void *ctx) {
    unsigned char *msg = malloc(sizeof(int) + record_size);
    /* The record is computed in its own (suitably aligned) allocation: msg +
     * sizeof(int) is not aligned for a struct of doubles. */
    void *record = malloc(record_size);
    int i;
    if (!msg || !record) _exit(3);
    for (i = start; i < n; ++i) {
        memset(record, 0, record_size);
        fn(ctx, i, record);
        memcpy(msg, &i, sizeof i);
        memcpy(msg + sizeof(int), record, record_size);
        if (write_all(fd, msg, sizeof(int) + record_size) != 0) _exit(4);
    }
    free(record);
    free(msg);
    _exit(0);
}

/* Reads one message or reports why not: 1 read, 0 timeout, -1 EOF/error. */
static int read_message(int fd, unsigned char *buf, size_t size, int timeout_ms) {
    size_t got = 0;
    while (got < size) {
        struct pollfd pfd;
        int pr;
        ssize_t r;
        pfd.fd = fd;
        pfd.events = POLLIN;
        pfd.revents = 0;
        pr = poll(&pfd, 1, timeout_ms);
        if (pr < 0 && errno == EINTR) continue;
        if (pr == 0) return 0;
        if (pr < 0) return -1;
        r = read(fd, buf + got, size - got);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return -1;
        got += (size_t)r;
    }
    return 1;
}

int guard_run(int n, size_t record_size, guard_case_fn fn, void *ctx, void *records,
              unsigned char *outcome, double timeout_seconds) {
    unsigned char *msg = malloc(sizeof(int) + record_size);
    int next = 0, bad = 0, timeout_ms = (int)(timeout_seconds * 1000.0);
    if (!msg) return -1;
    while (next < n) {
        int fds[2], status, r = -1;
        pid_t pid;
        if (pipe(fds) != 0) { free(msg); return -1; }
        pid = fork();
        if (pid < 0) { close(fds[0]); close(fds[1]); free(msg); return -1; }
        if (pid == 0) {
            close(fds[0]);
            free(msg); /* the parent's buffer, copied by fork */
            child_main(fds[1], next, n, record_size, fn, ctx);
        }
        close(fds[1]);
        while (next < n && (r = read_message(fds[0], msg, sizeof(int) + record_size,
                                             timeout_ms)) == 1) {
            int index;
            memcpy(&index, msg, sizeof index);
            if (index != next) break; /* cannot happen with one writer */
            memcpy((unsigned char *)records + (size_t)index * record_size, msg + sizeof(int),
                   record_size);
            outcome[index] = GUARD_OK;
            ++next;
        }
        if (next < n) {
            /* Timeout or child death while working on case `next`. */
            int hung = (r == 0);
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            outcome[next] = hung ? GUARD_HUNG : GUARD_CRASHED;
            memset((unsigned char *)records + (size_t)next * record_size, 0, record_size);
            ++bad;
            ++next;
        } else {
            waitpid(pid, &status, 0);
        }
        close(fds[0]);
    }
    free(msg);
    return bad;
}
