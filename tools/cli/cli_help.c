/* SPDX-License-Identifier: MIT */
/* The help texts: one page per subcommand, in the manner of a man page. */
#include "cli.h"

#include <string.h>

static const char help_main[] =
    "NAME\n"
    "    agjk - distance and collision between convex meshes by accelerated GJK\n"
    "\n"
    "SYNOPSIS\n"
    "    agjk distance A B [options]     distance, witness points, certified bound\n"
    "    agjk collide  A B [options]     Boolean collision test with early exit\n"
    "    agjk info     MESH [--json]     vertex counts, hull, bounding box\n"
    "    agjk hull     MESH -o OUT.off   write the convex hull (offline preprocessing)\n"
    "    agjk help [COMMAND] | agjk COMMAND --help | agjk --version\n"
    "\n"
    "DESCRIPTION\n"
    "    Each mesh file (OFF, OBJ, and any other format assimp reads: STL, PLY,\n"
    "    glTF, ...) stands for the convex hull of all its vertices: every mesh of\n"
    "    the scene is merged with its node transforms, and the hull is built with\n"
    "    Qhull. Faces do not matter; point clouds and line sets are fine. A flat,\n"
    "    collinear or single-point set has no solid hull: its points are used as\n"
    "    they are (still exact; `agjk info` says so). OFF, OBJ and ASCII PLY\n"
    "    coordinates are read in double precision (a PLY `float` property as\n"
    "    float); other formats in assimp's single precision.\n"
    "\n"
    "    Files are untrusted input: assimp runs in a child process with a time\n"
    "    budget and a memory cap, so a file that would crash or hang it gives\n"
    "    exit status 2 and a message naming the file.\n"
    "\n"
    "EXIT STATUS\n"
    "    0  success; for collide: the shapes collide (or touch within the tolerance)\n"
    "    1  collide only: the shapes are certified separated\n"
    "    2  error: bad command line, unreadable or malformed file, empty mesh,\n"
    "       NaN/Inf vertex, time or memory limit; a message goes to stderr\n"
    "    3  not converged: the iteration cap was reached first; the result is\n"
    "       printed with its certified bound, but no verdict is given\n"
    "\n"
    "Run `agjk help distance` (or collide, info, hull) for the options.\n";

static const char help_query_options[] =
    "POSES\n"
    "    --pose-a TX TY TZ QW QX QY QZ\n"
    "    --pose-b TX TY TZ QW QX QY QZ\n"
    "        Place mesh A (B) in the world: p_world = R(q) * (s * p_file) + t.\n"
    "        t = (TX, TY, TZ) is the translation; q = QW + QX i + QY j + QZ k is a\n"
    "        unit quaternion, scalar first, Hamilton convention, rotating the mesh\n"
    "        (active) from its file frame into the world frame: 1 0 0 0 is no\n"
    "        rotation, 0.7071068 0 0 0.7071068 turns +x into +y (90 degrees about z).\n"
    "        q and -q are the same rotation. The norm must be 1 to within 1e-5\n"
    "        (the quaternion is then renormalised); anything else is an error.\n"
    "        Default: identity (0 0 0 1 0 0 0).\n"
    "    --scale-a S, --scale-b S\n"
    "        Uniform scale S > 0 applied to the file coordinates before the pose\n"
    "        (e.g. 1000 for a file in metres queried in millimetres). Default 1.\n"
    "\n"
    "SOLVER\n"
    "    --method adaptive|gjk|nesterov|nesterov-normalized|polyak|fw\n"
    "        Direction policy of the Frank-Wolfe loop (Montaut et al., RSS 2022):\n"
    "        adaptive (the default: Polyak, then Nesterov when close, then GJK),\n"
    "        gjk (Alg. 4/5), nesterov (Alg. 6, best on curved shapes),\n"
    "        nesterov-normalized (Alg. 6 + 7, best on polytopes), polyak (heavy\n"
    "        ball, GJK++), fw (plain Frank-Wolfe, slow, for reference).\n"
    "    --tolerance T\n"
    "        Stop when the duality gap g <= T. Absolute mode: T is in length\n"
    "        units squared and certifies ||x - x*|| <= sqrt(T) (1e-8 means 1e-4\n"
    "        length units, the library's default for simulations). Default here:\n"
    "        1e-300, which the library raises to its floating-point floor: the\n"
    "        most accurate answer double precision can certify (see `bound`).\n"
    "    --relative\n"
    "        Read T as relative to the distance (dimensionless): the distance is\n"
    "        certified within a relative error of T / 2, whatever the units.\n"
    "        Shapes too close for the requested relative accuracy in double\n"
    "        precision end `not converged` (exit status 3).\n"
    "    --max-iterations N\n"
    "        Iteration cap, N >= 1 (default: the library's, 1000). Reaching it\n"
    "        gives exit status 3.\n"
    "    --scan\n"
    "        Find support points by scanning all hull vertices instead of hill\n"
    "        climbing over the hull's vertex graph (same answers; for comparison).\n"
    "\n"
    "OUTPUT\n"
    "    --json\n"
    "        Print one JSON object: query, status, colliding (collide only:\n"
    "        true, false, or null when not converged), distance, bound, gap,\n"
    "        witness_a, witness_b, normal (arrays of 3 numbers), iterations,\n"
    "        support_calls, momentum_stop_iteration, method, tolerance,\n"
    "        tolerance_mode, max_iterations. Numbers have 17 significant digits.\n"
    "        Without --json the same fields are printed as `key: value` lines.\n";

static const char help_limits[] =
    "LIMITS\n"
    "    --timeout SECONDS\n"
    "        Give up with exit status 2 after this long (default 300; 0: none).\n"
    "    --memory-limit MB\n"
    "        Cap the address space so that a file whose header claims billions\n"
    "        of elements fails cleanly (default: max(2048, 100 x total input file\n"
    "        size) MB; 0: no cap).\n";

static const char help_distance[] =
    "NAME\n"
    "    agjk distance - distance between the convex hulls of two meshes\n"
    "\n"
    "SYNOPSIS\n"
    "    agjk distance A B [--pose-a ...] [--pose-b ...] [--scale-a S] [--scale-b S]\n"
    "                  [--method M] [--tolerance T] [--relative] [--max-iterations N]\n"
    "                  [--scan] [--json] [--timeout S] [--memory-limit MB]\n"
    "\n"
    "DESCRIPTION\n"
    "    Computes the distance between hull(A) and hull(B) in their poses, with\n"
    "    the closest points (witness_a on A, witness_b on B, world frame), the\n"
    "    unit normal from A towards B, and a certified bound: the true distance\n"
    "    lies in [max(0, distance - bound), distance]. Status is `separated`,\n"
    "    `intersecting` (distance 0; penetration depth is not computed),\n"
    "    `contact within tolerance` (the shapes touch to within the tolerance),\n"
    "    or `not converged` (exit status 3).\n"
    "\n"
    "EXAMPLE\n"
    "    agjk distance examples/meshes/cube.off examples/meshes/sphere.obj \\\n"
    "        --pose-b 2 0 0 1 0 0 0\n"
    "    (unit cube at the origin, unit sphere at x = 2: distance 0.5, less the\n"
    "    small tessellation error of the sphere mesh)\n"
    "\n";

static const char help_collide[] =
    "NAME\n"
    "    agjk collide - do the convex hulls of two meshes intersect?\n"
    "\n"
    "SYNOPSIS\n"
    "    agjk collide A B [same options as agjk distance]\n"
    "\n"
    "DESCRIPTION\n"
    "    Boolean query with early exit (Montaut et al. 2022, Alg. 2): stops at\n"
    "    the first plane that separates the shapes, or when the origin is found\n"
    "    inside the Minkowski difference. No witness points or distance are\n"
    "    computed (printed as 0); `normal` is the separating plane's normal.\n"
    "\n"
    "    Exit status 0: intersecting, or touching to within the tolerance (the\n"
    "    safe answer for a collision check; --json tells `contact within\n"
    "    tolerance` apart); 1: certified separated; 2: error; 3: not converged.\n"
    "    In a script: if agjk collide a.off b.off --pose-b ...; then echo hit; fi\n"
    "    (status 3 and 2 are not 'separated': test $? when it matters.)\n"
    "\n";

static const char help_info[] =
    "NAME\n"
    "    agjk info - describe a mesh file and its convex hull\n"
    "\n"
    "SYNOPSIS\n"
    "    agjk info MESH [--json] [--timeout S] [--memory-limit MB]\n"
    "\n"
    "DESCRIPTION\n"
    "    Prints the file's format, number of meshes, faces and vertices (after\n"
    "    merging identical vertices), whether coordinates were read in double\n"
    "    precision, the hull kind (solid, flat (coplanar), collinear, single\n"
    "    point), the hull's vertex and triangle counts, which support function\n"
    "    queries will use, and the axis-aligned bounding box of the vertices.\n"
    "    --json prints the same as one JSON object.\n";

static const char help_hull[] =
    "NAME\n"
    "    agjk hull - write the convex hull of a mesh as an OFF file\n"
    "\n"
    "SYNOPSIS\n"
    "    agjk hull MESH -o OUT.off [--timeout S] [--memory-limit MB]\n"
    "\n"
    "DESCRIPTION\n"
    "    Builds the convex hull with Qhull and writes its extreme vertices\n"
    "    (17 significant digits, so doubles round-trip) and outward-oriented\n"
    "    triangles. Preprocess once, offline; a program embedding agjk can then\n"
    "    load the OFF's vertices into an agjk_polytope and build the adjacency\n"
    "    with agjk_polytope_build_adjacency() from the triangles. `-o -` writes\n"
    "    to standard output. A degenerate (flat, collinear, single-point) hull\n"
    "    is written as its distinct points with no faces, with a warning.\n";

void cli_print_help(const char *command, FILE *out) {
    if (!command) {
        fputs(help_main, out);
    } else if (strcmp(command, "distance") == 0 || strcmp(command, "collide") == 0) {
        fputs(strcmp(command, "distance") == 0 ? help_distance : help_collide, out);
        fputs(help_query_options, out);
        fputs("\n", out);
        fputs(help_limits, out);
    } else if (strcmp(command, "info") == 0) {
        fputs(help_info, out);
        fputs("\n", out);
        fputs(help_limits, out);
    } else if (strcmp(command, "hull") == 0) {
        fputs(help_hull, out);
        fputs("\n", out);
        fputs(help_limits, out);
    } else {
        fputs(help_main, out);
    }
}
