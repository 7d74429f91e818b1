# pattern_checks.sh - geometric facts about a printed point pattern, recomputed
# with awk from the "x y" lines rather than taken from the program's report.
# Sourced by check-cli.sh; each function is a test (exit status 0 when it holds)
# and names the offending points or probe on stderr when it does not:
#   two_numbers FILE                      every line is two decimal numbers
#   inside FILE X0 Y0 X1 Y1               every point in the closed rectangle
#   min_dist_ok FILE R                    every pair at least R apart (all pairs)
#   covered FILE R X0 Y0 X1 Y1 STEP       every grid probe within R of a point
#   min_dist_grid, covered_grid           the same two through a grid of cells,
#                                         for patterns of thousands of points

# Every line is exactly two decimal floating-point numbers.
two_numbers() {
    awk 'BEGIN { num = "^-?[0-9]+(\\.[0-9]+)?([eE][-+]?[0-9]+)?$"; bad = 0 }
         NF != 2 || $1 !~ num || $2 !~ num { bad = 1; exit }
         END { exit bad }' "$1"
}

# inside FILE X0 Y0 X1 Y1: every point lies in the closed rectangle.
inside() {
    awk -v x0="$2" -v y0="$3" -v x1="$4" -v y1="$5" '
        $1 < x0 + 0 || $1 > x1 + 0 || $2 < y0 + 0 || $2 > y1 + 0 { bad = 1; exit }
        END { exit bad }' "$1"
}

# Both checks go through a grid of cells of side R (at least R wide, also
# around 0, where awk's int() merges two): a point within R of a point or probe
# lies in the 3 x 3 cells around it.
# min_dist_grid FILE R: every pair at least R apart.
min_dist_grid() {
    awk -v r="$2" '
        { x[NR] = $1; y[NR] = $2; c = int($1 / r) " " int($2 / r); cell[c] = cell[c] " " NR }
        END {
            r2 = r * r * (1 - 1e-12)
            for (i = 1; i <= NR; i++) {
                cx = int(x[i] / r); cy = int(y[i] / r)
                for (a = cx - 1; a <= cx + 1; a++)
                    for (b = cy - 1; b <= cy + 1; b++) {
                        m = split(cell[a " " b], ids, " ")
                        for (k = 1; k <= m; k++) {
                            j = ids[k] + 0
                            if (j <= i) continue
                            dx = x[i] - x[j]; dy = y[i] - y[j]
                            if (dx * dx + dy * dy < r2) {
                                printf "points %d and %d closer than %s\n", i, j, r > "/dev/stderr"
                                exit 1
                            }
                        }
                    }
            }
        }' "$1"
}

# covered_grid FILE R X0 Y0 X1 Y1 STEP: every probe of a STEP grid over the
# rectangle is within R of some point (a necessary condition for maximality,
# checked independently of the library).
covered_grid() {
    awk -v r="$2" -v x0="$3" -v y0="$4" -v x1="$5" -v y1="$6" -v h="$7" '
        { x[NR] = $1; y[NR] = $2; c = int($1 / r) " " int($2 / r); cell[c] = cell[c] " " NR }
        END {
            r2 = r * r * (1 + 1e-12)
            nx = int((x1 - x0) / h + 0.5); ny = int((y1 - y0) / h + 0.5)
            for (a = 0; a <= nx; a++)
                for (b = 0; b <= ny; b++) {
                    px = x0 + (x1 - x0) * a / nx; py = y0 + (y1 - y0) * b / ny
                    cx = int(px / r); cy = int(py / r); hit = 0
                    for (u = cx - 1; u <= cx + 1 && !hit; u++)
                        for (v = cy - 1; v <= cy + 1 && !hit; v++) {
                            m = split(cell[u " " v], ids, " ")
                            for (k = 1; k <= m && !hit; k++) {
                                dx = x[ids[k]] - px; dy = y[ids[k]] - py
                                if (dx * dx + dy * dy <= r2) hit = 1
                            }
                        }
                    if (!hit) {
                        printf "probe (%g, %g) is farther than %s from every point\n",
                               px, py, r > "/dev/stderr"
                        exit 1
                    }
                }
        }' "$1"
}

# The names the checks use for small patterns: the same grid checks.
min_dist_ok() { min_dist_grid "$@"; }
covered() { covered_grid "$@"; }
