/* SPDX-License-Identifier: MIT */
/* Strict readers for the two text formats the tools see most: OFF and OBJ.
 *
 * assimp (as packaged) reads these formats into floats with a fast parser
 * that is not always right (an OBJ integer of 21 digits becomes 0, a 4,100-digit
 * coordinate a value that is not in the file), drops vertices that no face
 * uses, and accepts OFF faces whose indices are out of range. Here every
 * vertex record of the file is a point of the shape, every coordinate is
 * converted by strtod (correctly rounded to double), and anything that is not
 * a well-formed record is an error naming the file and the line:
 *
 * - numbers: [+-] digits [. digits] [(e|E) [+-] digits]; NaN and Inf are "not
 *   finite", a magnitude beyond AGJK_MAX_COORDINATE (overflow included) is
 *   "out of range"; a value below the smallest normal double is rounded like
 *   any other (its absolute error is below 1e-307);
 * - OFF ([ST][C][N]OFF; counts "V F [E]"): exactly V vertex lines (x y z, then
 *   at most 9 more numbers: normal, colour, texture coordinates), exactly F
 *   face lines (n >= 1, n indices in 0..V-1, at most 4 colour numbers), then
 *   nothing but comments; the 4OFF, nOFF and binary variants are refused;
 * - OBJ: v (3, 4, 6 or 7 numbers), vt, vn, vp (numbers), f, l, p (indices
 *   "v", "v/t", "v/t/n", "v//n", 1-based or negative relative, within the
 *   file's v, vt and vn counts), grouping, material and free-form statements
 *   (ignored); any other statement is an error.
 *
 * Line ends may be LF, CRLF or CR; a UTF-8 byte order mark is skipped; '#'
 * starts a comment; an OBJ line ending in '\' continues on the next line.
 * The whole file is read into memory once (no line length limit). */
#include "mesh.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* "1e50": the limit as written in agjk/types.h. */
#define LIMIT_TEXT_(x) #x
#define LIMIT_TEXT(x) LIMIT_TEXT_(x)

typedef struct reader {
    const char *path;
    char *buf;          /* the file, NUL-terminated; lines are cut in place */
    size_t len;
    char *next;         /* start of the next line */
    long line;          /* number of the current line (1-based) */
    long next_line;     /* number of the next line */
    char *err;
    size_t err_size;
} reader;

static void fail(reader *r, const char *fmt, ...) {
    va_list ap;
    int n = snprintf(r->err, r->err_size, "%s:%ld: ", r->path, r->line);
    if (n < 0 || (size_t)n >= r->err_size) return;
    va_start(ap, fmt);
    vsnprintf(r->err + n, r->err_size - (size_t)n, fmt, ap);
    va_end(ap);
}

/* Reads the whole file. */
static int read_file(reader *r, const char *path, char *err, size_t err_size) {
    memset(r, 0, sizeof *r);
    r->path = path;
    r->err = err;
    r->err_size = err_size;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: %s", path, strerror(errno));
        return 0;
    }
    /* Sized by the file (grown if it grows while we read). */
    struct stat st;
    size_t cap = 1 << 16, len = 0;
    if (fstat(fileno(f), &st) == 0 && st.st_size > 0 && (uintmax_t)st.st_size < SIZE_MAX / 2)
        cap = (size_t)st.st_size + 1;
    char *buf = NULL;
    for (;;) {
        char *bigger = realloc(buf, cap + 1);
        if (!bigger) {
            free(buf);
            fclose(f);
            snprintf(err, err_size, "%s: out of memory reading the file", path);
            return 0;
        }
        buf = bigger;
        len += fread(buf + len, 1, cap - len, f);
        if (len < cap) break;
        cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) {
        free(buf);
        snprintf(err, err_size, "%s: read error", path);
        return 0;
    }
    buf[len] = '\0';
    r->buf = buf;
    r->len = len;
    r->next = buf;
    r->next_line = 1;
    /* A UTF-8 byte order mark (Windows editors). */
    if (len >= 3 && (unsigned char)buf[0] == 0xEF && (unsigned char)buf[1] == 0xBB &&
        (unsigned char)buf[2] == 0xBF)
        r->next += 3;
    return 1;
}

/* Line number of byte `at` (for the rare error found by a whole-file scan). */
static long line_of(const reader *r, const char *at) {
    long line = 1;
    for (const char *s = r->buf; s < at; s++)
        if (*s == '\n' || (*s == '\r' && s[1] != '\n')) line++;
    return line;
}

static int check_text(reader *r, const char *format) {
    const char *nul = memchr(r->buf, '\0', r->len);
    if (!nul) return 1;
    r->line = line_of(r, nul);
    fail(r, "NUL byte in a text %s file: binary data, or a UTF-16 or UTF-32 encoding "
         "(save it as UTF-8 or ASCII)", format);
    return 0;
}

/* Cuts the next line (without its end and comment) out of the buffer;
 * returns NULL at the end of the file. `continuation`: a line ending in '\'
 * goes on with the next one (OBJ), unless the '\' ends a comment. */
static char *next_line(reader *r, int continuation) {
    if (r->next >= r->buf + r->len) return NULL;
    char *start = r->next, *s = start;
    r->line = r->next_line;
    for (;;) {
        while (*s && *s != '\n' && *s != '\r') s++;
        char *end = s;
        if (*s == '\r' && s[1] == '\n') s += 2;
        else if (*s) s++;
        r->next_line++;
        /* A '\' just before the line end (blanks allowed after it). */
        char *b = end;
        while (b > start && (b[-1] == ' ' || b[-1] == '\t')) b--;
        if (continuation && *end && b > start && b[-1] == '\\' &&
            !memchr(start, '#', (size_t)(b - start))) { /* not inside a comment */
            b[-1] = ' ';
            for (char *c = end; c < s; c++) *c = ' ';
            continue;
        }
        *end = '\0';
        break;
    }
    r->next = s;
    char *hash = strchr(start, '#');
    if (hash) *hash = '\0';
    return start;
}

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

/* Splits off the next blank-separated token; NULL when the line is done. */
static char *token(char **line) {
    char *s = *line;
    while (is_blank(*s)) s++;
    if (!*s) {
        *line = s;
        return NULL;
    }
    char *t = s;
    while (*s && !is_blank(*s)) s++;
    if (*s) *s++ = '\0';
    *line = s;
    return t;
}

/* The token, shortened for a message. */
static const char *shown(const char *tok, char *buf, size_t size) {
    size_t n = strlen(tok);
    if (n < 40) return tok;
    snprintf(buf, size, "%.24s... (%zu characters)", tok, n);
    return buf;
}

/* 1 if `t` is a decimal number by the syntax above. */
static int is_decimal(const char *t) {
    int digits = 0;
    if (*t == '+' || *t == '-') t++;
    while (*t >= '0' && *t <= '9') t++, digits++;
    if (*t == '.') {
        t++;
        while (*t >= '0' && *t <= '9') t++, digits++;
    }
    if (!digits) return 0;
    if (*t == 'e' || *t == 'E') {
        t++;
        if (*t == '+' || *t == '-') t++;
        if (!(*t >= '0' && *t <= '9')) return 0;
        while (*t >= '0' && *t <= '9') t++;
    }
    return *t == '\0';
}

static int is_nonfinite_word(const char *t) {
    if (*t == '+' || *t == '-') t++;
    char w[4] = {0};
    for (int i = 0; i < 3 && t[i]; i++) w[i] = (char)(t[i] | 0x20);
    return strcmp(w, "nan") == 0 || strcmp(w, "inf") == 0;
}

int mesh_parse_coordinate(const char *t, double *value) {
    if (!is_decimal(t))
        return is_nonfinite_word(t) ? MESH_NUMBER_NOT_FINITE : MESH_NUMBER_NOT_A_NUMBER;
    char *end;
    double v = strtod(t, &end);
    /* strtod follows LC_NUMERIC: in a decimal-comma locale it would stop at
     * the '.', so a partial conversion is refused rather than misread. */
    if (*end) return MESH_NUMBER_NOT_A_NUMBER;
    if (!(fabs(v) <= AGJK_MAX_COORDINATE)) return MESH_NUMBER_OUT_OF_RANGE;
    *value = v;
    return MESH_NUMBER_OK;
}

void mesh_coordinate_error(int code, const char *t, char *msg, size_t size) {
    char b[64];
    if (code == MESH_NUMBER_NOT_FINITE)
        snprintf(msg, size, "coordinate '%s' is not finite (NaN or Inf)", shown(t, b, sizeof b));
    else if (code == MESH_NUMBER_OUT_OF_RANGE)
        snprintf(msg, size, "coordinate '%s' is out of range (limit %s)", shown(t, b, sizeof b),
                 LIMIT_TEXT(AGJK_MAX_COORDINATE));
    else
        snprintf(msg, size, "'%s' is not a number", shown(t, b, sizeof b));
}

/* A coordinate: a decimal number of magnitude at most AGJK_MAX_COORDINATE. */
static int coordinate(reader *r, const char *t, double *out) {
    int code = mesh_parse_coordinate(t, out);
    if (code != MESH_NUMBER_OK) {
        char msg[160];
        mesh_coordinate_error(code, t, msg, sizeof msg);
        fail(r, "%s", msg);
        return 0;
    }
    return 1;
}

/* A decimal integer (sign allowed) into *out; 0 if not one or beyond +-2^62. */
static int integer(const char *t, const char *end, int64_t *out) {
    int neg = 0;
    int64_t v = 0;
    if (t < end && (*t == '+' || *t == '-')) neg = *t++ == '-';
    if (t == end) return 0;
    for (; t < end; t++) {
        if (*t < '0' || *t > '9') return 0;
        if (v > ((int64_t)1 << 62) / 10) return 0;
        v = v * 10 + (*t - '0');
    }
    *out = neg ? -v : v;
    return 1;
}

/* Growing point array. */
typedef struct point_list {
    agjk_vec3 *p;
    size_t count, capacity;
} point_list;

static int push_point(reader *r, point_list *l, const double c[3]) {
    if (l->count == l->capacity) {
        size_t cap = l->capacity ? 2 * l->capacity : 1024;
        agjk_vec3 *n = realloc(l->p, cap * sizeof *n);
        if (!n) {
            fail(r, "out of memory");
            return 0;
        }
        l->p = n;
        l->capacity = cap;
    }
    agjk_vec3 *v = &l->p[l->count++];
    v->x = c[0];
    v->y = c[1];
    v->z = c[2];
    return 1;
}

/* ---- OFF ------------------------------------------------------------------ */

/* Next line with content; NULL at the end of the file. */
static char *content_line(reader *r, int continuation) {
    char *line;
    while ((line = next_line(r, continuation))) {
        char *s = line;
        while (is_blank(*s)) s++;
        if (*s) return s;
    }
    return NULL;
}

/* "V F [E]" counts. */
static int off_counts(reader *r, char *s, int64_t counts[3]) {
    int n = 0;
    char *t, b[64];
    while ((t = token(&s))) {
        if (n == 3 || !integer(t, t + strlen(t), &counts[n]) || counts[n] < 0) {
            fail(r, "OFF header: expected 'vertices faces [edges]' (non-negative integers), "
                 "found '%s'", shown(t, b, sizeof b));
            return 0;
        }
        n++;
    }
    if (n == 1) {
        fail(r, "OFF header: the face count is missing (expected 'vertices faces [edges]')");
        return 0;
    }
    return n;
}

static int read_off(reader *r, point_list *pts, size_t *face_count) {
    char *s = content_line(r, 0), *t, b[64];
    if (!s) {
        snprintf(r->err, r->err_size, "%s: no OFF header (empty or comment-only file)", r->path);
        return 0;
    }
    t = token(&s);
    size_t klen = strlen(t);
    size_t pre = 0;
    if (strncmp(t, "ST", 2) == 0) pre += 2;
    if (t[pre] == 'C') pre++;
    if (t[pre] == 'N') pre++;
    if (klen < 3 || strcmp(t + klen - 3, "OFF") != 0) {
        fail(r, "not an OFF file: the first line is '%s', not OFF", shown(t, b, sizeof b));
        return 0;
    }
    if (pre != klen - 3) {
        fail(r, "unsupported OFF variant '%s' (only [ST][C][N]OFF in 3-D)", shown(t, b, sizeof b));
        return 0;
    }
    char *rest = s;
    while (is_blank(*rest)) rest++;
    if (strncmp(rest, "BINARY", 6) == 0) {
        fail(r, "binary OFF is not supported (write it as text)");
        return 0;
    }
    int64_t counts[3] = {0, 0, 0};
    if (!*rest) {
        if (!(s = content_line(r, 0))) {
            fail(r, "OFF header: the file ends before the vertex and face counts");
            return 0;
        }
    }
    if (!off_counts(r, s, counts)) return 0;
    long header_line = r->line;
    /* A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 2: counts
     * beyond that are a truncated file or a bid to exhaust memory. */
    if ((double)counts[0] * 6.0 + (double)counts[1] * 2.0 > (double)r->len) {
        fail(r, "OFF header declares %lld vertices and %lld faces, more than the file's %zu "
             "bytes can hold (truncated or malformed)", (long long)counts[0],
             (long long)counts[1], r->len);
        return 0;
    }
    if (counts[0] == 0) {
        fail(r, "OFF header declares no vertices (empty mesh)");
        return 0;
    }
    int64_t nv = counts[0], nf = counts[1];
    pts->p = malloc((size_t)nv * sizeof *pts->p);
    if (!pts->p) {
        fail(r, "out of memory for %lld vertices", (long long)nv);
        return 0;
    }
    pts->capacity = (size_t)nv;
    for (int64_t i = 0; i < nv; i++) {
        if (!(s = content_line(r, 0))) {
            r->line = r->next_line - 1;
            fail(r, "the file ends after %lld of the %lld vertices declared on line %ld",
                 (long long)i, (long long)nv, header_line);
            return 0;
        }
        double c[3];
        int n = 0;
        while ((t = token(&s))) {
            double v;
            if (!coordinate(r, t, &v)) return 0;
            if (n < 3) c[n] = v;
            n++;
        }
        if (n < 3 || n > 12) {
            fail(r, "vertex %lld has %d numbers; expected x y z (and at most 9 more: normal, "
                 "colour, texture coordinates)", (long long)i, n);
            return 0;
        }
        if (!push_point(r, pts, c)) return 0;
    }
    for (int64_t f = 0; f < nf; f++) {
        if (!(s = content_line(r, 0))) {
            r->line = r->next_line - 1;
            fail(r, "the file ends after %lld of the %lld faces declared on line %ld",
                 (long long)f, (long long)nf, header_line);
            return 0;
        }
        int64_t k;
        t = token(&s);
        if (!integer(t, t + strlen(t), &k) || k < 1) {
            fail(r, "face %lld: the vertex count '%s' is not a positive integer", (long long)f,
                 shown(t, b, sizeof b));
            return 0;
        }
        for (int64_t j = 0; j < k; j++) {
            int64_t idx;
            if (!(t = token(&s))) {
                fail(r, "face %lld declares %lld vertices but lists %lld", (long long)f,
                     (long long)k, (long long)j);
                return 0;
            }
            if (!integer(t, t + strlen(t), &idx)) {
                fail(r, "face %lld: vertex index '%s' is not an integer", (long long)f,
                     shown(t, b, sizeof b));
                return 0;
            }
            if (idx < 0 || idx >= nv) {
                fail(r, "face %lld: vertex index %s is out of range (the file has %lld "
                     "vertices, indices 0..%lld)", (long long)f, shown(t, b, sizeof b),
                     (long long)nv, (long long)nv - 1);
                return 0;
            }
        }
        int extra = 0;
        while ((t = token(&s))) {
            if (!is_decimal(t) || ++extra > 4) {
                fail(r, "face %lld: unexpected '%s' after its %lld vertex indices (at most 4 "
                     "colour numbers may follow)", (long long)f, shown(t, b, sizeof b),
                     (long long)k);
                return 0;
            }
        }
    }
    if ((s = content_line(r, 0))) {
        fail(r, "unexpected data after the %lld faces declared on line %ld",
             (long long)nf, header_line);
        return 0;
    }
    *face_count = (size_t)nf;
    return 1;
}

/* ---- OBJ ------------------------------------------------------------------ */

/* Statements that carry no vertex positions and are ignored (OBJ spec:
 * grouping, display and render attributes, free-form geometry). */
static const char *const obj_ignored[] = {
    "o", "g", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "lod", "bevel", "c_interp",
    "d_interp", "shadow_obj", "trace_obj", "ctech", "stech", "cstype", "deg", "bmat", "step",
    "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "call", "csh",
    "res"};

/* Index references of one kind (v, vt or vn): the largest positive one is
 * checked against the final count, so forward references are allowed. */
typedef struct index_kind {
    const char *name;
    size_t count;     /* records so far */
    int64_t max_seen; /* largest positive index */
    long max_line;
} index_kind;

static int obj_index(reader *r, const char *t, const char *end, index_kind *k, const char *tok) {
    int64_t i;
    char b[64];
    if (!integer(t, end, &i)) {
        fail(r, "'%s' is not a valid index reference (expected v, v/vt, v/vt/vn or v//vn)",
             shown(tok, b, sizeof b));
        return 0;
    }
    if (i == 0) {
        fail(r, "index 0 in '%s' (OBJ indices start at 1)", shown(tok, b, sizeof b));
        return 0;
    }
    if (i < 0 && (uint64_t)-i > k->count) {
        fail(r, "relative %s index %lld in '%s' is out of range (%zu %s records so far)",
             k->name, (long long)i, shown(tok, b, sizeof b), k->count, k->name);
        return 0;
    }
    if (i > k->max_seen) {
        k->max_seen = i;
        k->max_line = r->line;
    }
    return 1;
}

static int read_obj(reader *r, point_list *pts, size_t *face_count) {
    index_kind kinds[3] = {{"v", 0, 0, 0}, {"vt", 0, 0, 0}, {"vn", 0, 0, 0}};
    char *s, *t, b[64];
    *face_count = 0;
    while ((s = content_line(r, 1))) {
        char *key = token(&s);
        if (strcmp(key, "v") == 0) {
            double c[3];
            int n = 0;
            while ((t = token(&s))) {
                double v;
                if (n < 7 && !coordinate(r, t, &v)) return 0;
                if (n < 3) c[n] = v;
                n++;
            }
            if (n != 3 && n != 4 && n != 6 && n != 7) {
                fail(r, "vertex with %s%d numbers; expected x y z, x y z w or x y z r g b [a]",
                     n > 7 ? "more than " : "", n > 7 ? 7 : n);
                return 0;
            }
            if (!push_point(r, pts, c)) return 0;
            kinds[0].count++;
        } else if (strcmp(key, "vt") == 0 || strcmp(key, "vn") == 0 || strcmp(key, "vp") == 0) {
            int n = 0;
            while ((t = token(&s))) {
                if (!is_decimal(t)) {
                    fail(r, "'%s' in a %s record is not a number", shown(t, b, sizeof b), key);
                    return 0;
                }
                n++;
            }
            if (n < 1 || n > 4) {
                fail(r, "%s record with %d numbers", key, n);
                return 0;
            }
            if (key[1] == 't') kinds[1].count++;
            if (key[1] == 'n') kinds[2].count++;
        } else if (strcmp(key, "f") == 0 || strcmp(key, "l") == 0 || strcmp(key, "p") == 0) {
            int n = 0;
            while ((t = token(&s))) {
                /* v[/[vt][/vn]] */
                const char *part = t;
                for (int k = 0; k < 3; k++) {
                    const char *slash = strchr(part, '/');
                    const char *end = slash ? slash : part + strlen(part);
                    if (k == 2 && slash) {
                        fail(r, "'%s' is not a valid index reference (expected v, v/vt, "
                             "v/vt/vn or v//vn)", shown(t, b, sizeof b));
                        return 0;
                    }
                    /* The position is required; vt may be empty when vn follows. */
                    if ((k == 0 || end > part || !slash) &&
                        !obj_index(r, part, end, &kinds[k], t))
                        return 0;
                    if (!slash) break;
                    part = slash + 1;
                }
                n++;
            }
            if (n < 1) {
                fail(r, "'%s' record without vertex indices", key);
                return 0;
            }
            (*face_count)++;
        } else {
            size_t i, known = sizeof obj_ignored / sizeof obj_ignored[0];
            for (i = 0; i < known && strcmp(key, obj_ignored[i]) != 0; i++) {}
            if (i == known) {
                fail(r, "unknown OBJ statement '%s'", shown(key, b, sizeof b));
                return 0;
            }
        }
    }
    for (int k = 0; k < 3; k++)
        if ((uint64_t)kinds[k].max_seen > kinds[k].count) {
            r->line = kinds[k].max_line;
            fail(r, "%s index %lld is out of range (the file has %zu %s records)",
                 kinds[k].name, (long long)kinds[k].max_seen, kinds[k].count, kinds[k].name);
            return 0;
        }
    if (pts->count == 0) {
        snprintf(r->err, r->err_size, "%s: no vertices (empty mesh)", r->path);
        return 0;
    }
    return 1;
}

int mesh_read_text(const char *path, const char *format, mesh_points *out, char *err,
                   size_t err_size) {
    int is_off = strcmp(format, "off") == 0;
    char fmt[sizeof out->format];
    reader r;
    snprintf(fmt, sizeof fmt, "%s", format); /* `format` may be out->format */
    memset(out, 0, sizeof *out);
    memcpy(out->format, fmt, sizeof fmt);
    if (!read_file(&r, path, err, err_size)) return 0;
    point_list pts = {NULL, 0, 0};
    size_t faces = 0;
    int ok = check_text(&r, is_off ? "OFF" : "OBJ") &&
             (is_off ? read_off(&r, &pts, &faces) : read_obj(&r, &pts, &faces));
    free(r.buf);
    if (!ok) {
        free(pts.p);
        return 0;
    }
    out->points = pts.p;
    out->count = pts.count;
    out->mesh_count = 1;
    out->face_count = faces;
    out->double_precision = 1;
    return 1;
}
