/* SPDX-License-Identifier: MIT */
/* agjk against Coal 3.0.3 on the benchmark's problems: the same method (GJK,
 * Nesterov, Nesterov with normalization, Polyak), the same tolerance, cap and
 * initial guess, in the same process with the same clock, each problem timed
 * for agjk and right after for Coal. Coal is optional (tools/fetch-coal.sh);
 * without it the report says how to get it. */
#ifndef AGJK_BENCH_COAL_BENCH_H
#define AGJK_BENCH_COAL_BENCH_H

#include "bench.h"
#include "repeat.h"

/* One problem x method x mode, answered and timed by both libraries. */
typedef struct coal_bench_record {
    bench_record agjk, coal;   /* judged by bench_evaluate(); Coal has no certified
                                  bound (coal.run.bound = -1) */
    int coal_status;           /* coal::details::GJK::Status */
    unsigned char agjk_off, coal_off; /* distance mode: a converged answer farther than
                                         sqrt(tolerance) from the reference (outside the
                                         duality gap's guarantee) */
} coal_bench_record;

typedef struct coal_bench_data {
    coal_bench_record *recs;
    int count;
    int processes;             /* the times are medians over this many processes (repeat.h) */
    int skipped_problems;      /* a shape without a Coal counterpart (no solid hull) */
    int failed_runs;           /* Coal threw */
    double seconds;
    const char *version;
} coal_bench_data;

/* Coal's counterpart of a benchmark shape (coal_adapter_shape_new; NULL for a
 * polytope without a solid hull), and a pose in the adapter's layout (row-major
 * rotation, translation). */
void *coal_bench_shape(const bench_shape *s);
void coal_bench_pose(const agjk_pose *p, double r[9], double t[3]);

/* Runs the comparison when Coal was built in and cfg->coal_reps > 0; returns
 * NULL (after saying why on stderr) otherwise. The tolerance of a problem is
 * cfg->tolerance x its scale^2. */
coal_bench_data *coal_bench_run(const bench_config *cfg, const bench_set *set);
/* The same on any set, quietly but for a progress line headed by label
 * (NULL without Coal or with cfg->coal_reps <= 0). */
coal_bench_data *coal_bench_run_set(const bench_config *cfg, const bench_set *set,
                                    const char *label);
void coal_bench_free(coal_bench_data *d);

/* The columns of agjk's and Coal's times of d's records (repeat.h), for the
 * comparison repeated in fresh processes; returns 2 (0 when d is empty, with
 * nothing to repeat). */
int coal_bench_times(coal_bench_data *d, bench_times out[2]);

/* The methods both libraries have (bench_method values) and their short names. */
extern const int coal_bench_methods[4];
extern const char *const coal_bench_method_short[4];

/* Aggregates of one family x category x method x mode of a run. */
typedef struct coal_bench_group {
    int n, agjk_wrong, coal_wrong, agjk_off, coal_off, agjk_nc, coal_nc, slower;
    int agjk_violations;       /* agjk's certified interval misses the reference */
    double ratio_median, ratio_of_means, agjk_ns, coal_ns;
    double agjk_it, coal_it, agjk_calls, coal_calls;
} coal_bench_group;

/* buf_*: scratch of d->count doubles each. */
coal_bench_group coal_bench_group_of(const bench_set *set, const coal_bench_data *d, int family,
                                     int category, int method, int mode, double *buf_ratio,
                                     double *buf_a, double *buf_c);
/* 1 when the two libraries did different work (mean support calls more than
 * 5% apart): the ratio then compares different computations. */
int coal_bench_different_work(const coal_bench_group *g);
/* A ratio table cell: bold when agjk is slower, a dagger when differ. */
void coal_bench_cell(FILE *f, double v, int differ);

/* Answers of a run against the certified reference, added up over records. */
typedef struct coal_bench_answers {
    int runs;
    int agjk_wrong, coal_wrong;   /* verdicts the reference refutes */
    int agjk_off, coal_off;       /* converged distances off by more than sqrt(tolerance) */
    int agjk_nc, coal_nc;         /* no verdict */
    int agjk_violations;          /* agjk's certified interval misses the reference */
    int agjk_contact;             /* agjk's contact within tolerance */
} coal_bench_answers;
/* Adds d's records to *a (which the caller zeroes first). */
void coal_bench_count_answers(const coal_bench_data *d, coal_bench_answers *a);

/* A details table: its markdown header (first column `set_title`) on md, and
 * its CSV at path with its header line (first column `set_column`), which it
 * returns (NULL, said on stderr, when it cannot be written); with_misses
 * adds agjk's bound misses as a last column to both. */
FILE *coal_bench_details_open(FILE *md, const char *path, const char *set_title,
                              const char *set_column, int with_misses);
/* One row of a details table (markdown) and of its CSV (csv may be NULL). */
void coal_bench_detail_row(FILE *md, FILE *csv, const char *set, int category, int mode, int m,
                           const coal_bench_group *g, int with_misses);

/* A ratio table's header: `first` (the set's column title), the 8 method x
 * mode columns, then the `extra` column titles (may be NULL). */
void coal_bench_ratio_head(FILE *f, const char *first, const char *const *extra, int n_extra);

/* What a ratio table adds up to: the cells where both libraries did the same
 * work, those where agjk is slower and those at or below 0.8x, the cells left
 * out (different work), and the cells of each kind by name. */
typedef struct coal_bench_tally {
    int cells, slower, target, differ;
    char list[2][8192]; /* [0] cells where agjk is slower, [1] where it is not */
    size_t len[2];
} coal_bench_tally;
void coal_bench_tally_init(coal_bench_tally *t);
/* Counts the cell of group g (method index m into coal_bench_methods). */
void coal_bench_tally_add(coal_bench_tally *t, const coal_bench_group *g, const char *set,
                          const char *category, int mode, int m);
/* "<lead> the N cells ...: agjk is slower than Coal in ...", then the
 * target line; lead "Of" and where "", or e.g. "On the stress set, of" and
 * " on the stress set". */
void coal_bench_tally_write(FILE *f, const coal_bench_tally *t, const char *lead,
                            const char *where);

/* Appends the agjk/Coal section to <out>/tables.md (or, without Coal, how to
 * get it), writes <out>/coal.csv and coal-ratios.md, and prints the ratio
 * table on stdout. ccd: the libccd records (may be NULL). Returns 0 or -1. */
int coal_bench_write(const bench_report *r, const coal_bench_data *d);

#endif
