/* SPDX-License-Identifier: MIT */
/* Guards against inputs that would hang the tool or exhaust the machine.
 *
 * assimp trusts the element counts in file headers: an ASCII PLY declaring
 * 2e9 vertices makes it reserve tens of gigabytes and spin for minutes. Two
 * process-wide limits turn such files into clean errors:
 * - an address-space cap (RLIMIT_AS): allocations beyond it fail, assimp
 *   catches std::bad_alloc and returns an error we report;
 * - a watchdog (alarm): past the time limit we print a message and exit with
 *   the error status instead of running on.
 * Sanitizer builds reserve huge address ranges, so the cap is skipped there. */
#include "cli.h"

#include <signal.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CLI_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define CLI_SANITIZED 1
#endif
#endif
#ifndef CLI_SANITIZED
#define CLI_SANITIZED 0
#endif

/* Automatic cap: generous for real meshes (assimp needs well under 100 bytes
 * of memory per byte of text), never below 2 GiB. */
#define CLI_MEMORY_FLOOR_MB 2048.0
#define CLI_MEMORY_PER_FILE_BYTE 100.0

static void on_alarm(int sig) {
    static const char msg[] = "agjk: time limit exceeded (see --timeout); giving up\n";
    (void)sig;
    /* Only async-signal-safe calls here. */
    ssize_t unused = write(STDERR_FILENO, msg, sizeof msg - 1);
    (void)unused;
    _exit(CLI_EXIT_ERROR);
}

static void start_watchdog(double seconds) {
    if (!(seconds > 0)) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_alarm;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGALRM, &sa, NULL);
    alarm(seconds >= 1e6 ? 1000000u : (unsigned)(seconds + 0.999));
}

static void cap_memory(const cli_args *args) {
    double mb = args->memory_limit_mb;
    if (CLI_SANITIZED || mb == 0) return;
    if (mb < 0) {
        double bytes = 0;
        struct stat st;
        for (int i = 0; i < args->input_count; i++)
            if (stat(args->inputs[i], &st) == 0) bytes += (double)st.st_size;
        mb = bytes * CLI_MEMORY_PER_FILE_BYTE / (1024.0 * 1024.0);
        if (mb < CLI_MEMORY_FLOOR_MB) mb = CLI_MEMORY_FLOOR_MB;
    }
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) != 0) return;
    double cap = mb * 1024.0 * 1024.0;
    /* Never raise a limit the caller set; only lower. */
    if (rl.rlim_cur != RLIM_INFINITY && (double)rl.rlim_cur <= cap) return;
    rl.rlim_cur = (rlim_t)cap;
    setrlimit(RLIMIT_AS, &rl);
}

void cli_guard_start(const cli_args *args) {
    cap_memory(args);
    start_watchdog(args->timeout);
}
