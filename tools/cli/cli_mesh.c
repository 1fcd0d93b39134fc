/* SPDX-License-Identifier: MIT */
/* `agjk info MESH` and `agjk hull MESH -o OUT.off`. */
#include "cli.h"

#include <string.h>

static void info_text(const char *path, const cli_shape *s) {
    const mesh_hull *h = &s->hull;
    printf("%-17s %s\n", "file:", path);
    printf("%-17s %s\n", "format:", s->points.format[0] ? s->points.format : "(no extension)");
    printf("%-17s %zu\n", "meshes:", s->points.mesh_count);
    printf("%-17s %zu\n", "faces:", s->points.face_count);
    printf("%-17s %zu\n", "vertices:", s->points.count);
    printf("%-17s %s\n", "precision:",
           s->points.precision_note[0] ? s->points.precision_note
           : s->points.double_precision ? "double" : "float");
    printf("%-17s %s\n", "hull:", mesh_hull_kind(h));
    printf("%-17s %d\n", "hull_vertices:", (int)h->vertex_count);
    printf("%-17s %d\n", "hull_triangles:", (int)h->triangle_count);
    printf("%-17s %s\n", "support:", cli_hull_support_text(h));
    printf("%-17s %.17g %.17g %.17g\n", "bbox_min:", h->bbox_min.x, h->bbox_min.y, h->bbox_min.z);
    printf("%-17s %.17g %.17g %.17g\n", "bbox_max:", h->bbox_max.x, h->bbox_max.y, h->bbox_max.z);
}

static void info_json(const char *path, const cli_shape *s) {
    const mesh_hull *h = &s->hull;
    /* The path is printed as a JSON string: escape what JSON requires. */
    fputs("{\"file\": \"", stdout);
    for (const unsigned char *c = (const unsigned char *)path; *c; c++) {
        if (*c == '"' || *c == '\\') printf("\\%c", *c);
        else if (*c < 0x20) printf("\\u%04x", *c);
        else putchar(*c);
    }
    printf("\", \"format\": \"%s\", \"meshes\": %zu, \"faces\": %zu, \"vertices\": %zu, "
           "\"double_precision\": %s, \"hull\": \"%s\", \"hull_dimension\": %d, "
           "\"hull_vertices\": %d, \"hull_triangles\": %d, \"hill_climbing\": %s, "
           "\"bbox_min\": [%.17g, %.17g, %.17g], \"bbox_max\": [%.17g, %.17g, %.17g]}\n",
           s->points.format, s->points.mesh_count, s->points.face_count, s->points.count,
           s->points.double_precision ? "true" : "false", mesh_hull_kind(h), h->dimension,
           (int)h->vertex_count, (int)h->triangle_count,
           cli_hull_hill_climbing(h) ? "true" : "false", h->bbox_min.x, h->bbox_min.y,
           h->bbox_min.z, h->bbox_max.x, h->bbox_max.y, h->bbox_max.z);
}

int cli_cmd_info(int argc, char **argv) {
    cli_args a;
    int help;
    cli_args_init(&a);
    if (!cli_parse(argc, argv, 1, CLI_OPT_JSON, 1, &a, &help)) return CLI_EXIT_ERROR;
    if (help) {
        cli_print_help("info", stdout);
        return CLI_EXIT_OK;
    }
    cli_guard_start(&a);
    cli_shape s;
    if (!cli_shape_load(a.inputs[0], 1.0, CLI_SHAPE_HULL | CLI_SHAPE_ADJACENCY, &s))
        return CLI_EXIT_ERROR;
    if (a.json) info_json(a.inputs[0], &s);
    else info_text(a.inputs[0], &s);
    cli_shape_free(&s);
    return cli_flush_result() ? CLI_EXIT_OK : CLI_EXIT_ERROR;
}

int cli_cmd_hull(int argc, char **argv) {
    cli_args a;
    int help;
    cli_args_init(&a);
    if (!cli_parse(argc, argv, 1, CLI_OPT_OUTPUT, 1, &a, &help)) return CLI_EXIT_ERROR;
    if (help) {
        cli_print_help("hull", stdout);
        return CLI_EXIT_OK;
    }
    if (!a.output) {
        cli_error("hull needs -o OUT.off (or -o - for standard output)");
        return CLI_EXIT_ERROR;
    }
    cli_guard_start(&a);
    cli_shape s;
    if (!cli_shape_load(a.inputs[0], 1.0, CLI_SHAPE_HULL, &s)) return CLI_EXIT_ERROR;
    int to_stdout = strcmp(a.output, "-") == 0;
    FILE *f = to_stdout ? stdout : fopen(a.output, "w");
    int ok = f != NULL;
    if (!ok) cli_error("%s: cannot open for writing", a.output);
    if (ok && s.hull.dimension != 3)
        cli_error("%s: warning: the hull is %s; writing its %d points with no faces",
                  a.inputs[0], mesh_hull_kind(&s.hull), (int)s.hull.vertex_count);
    if (ok && !mesh_hull_write_off(&s.hull, f)) {
        cli_error("%s: write error", a.output);
        ok = 0;
    }
    if (f && !to_stdout && fclose(f) != 0 && ok) {
        cli_error("%s: write error", a.output);
        ok = 0;
    }
    cli_shape_free(&s);
    return ok ? CLI_EXIT_OK : CLI_EXIT_ERROR;
}
