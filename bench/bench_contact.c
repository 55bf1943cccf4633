/* Friction wrench: cost per evaluation vs cells and error against the
 * Contensou closed form (uniform COF, pole inside the disc, eps = 0.5),
 * polar and Cartesian layouts: a work-precision plot.  The cost is the
 * field-COF path (bilinear look-ups), the one the dynamics pays. */
#include "bench.h"
#include "contact.h"
#include "cof.h"
#include "result.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sort.h>

int bench_contact(FILE *f, const char *dir)
{
    size_t cells[2][6] = { { 4, 8, 12, 16, 32, 64 }, { 8, 16, 24, 32, 64, 128 } };
    double err[2][6], cost[2][6], npts[2][6];
    double g[16];
    for (int i = 0; i < 16; i++)
        g[i] = 0.5;
    sf_cof *grid;   /* a constant field on a grid: the interpolating path */
    sf_cof_alloc_grid(4, 4, -2, -2, 4.0 / 3.0, 4.0 / 3.0, g, &grid);
    double fe, te, w = 2.0, R = 0.5, N = 98.1, eps = 0.5;
    sf_contensou(eps, &fe, &te);
    fprintf(f, "## Friction wrench: cost vs accuracy\n\nOne wrench evaluation (Eqs. 7-8) over a COF grid (bilinear "
               "look-up per cell), against the closed form at eps = 0.5 (pole inside the disc, the hard case). "
               "Medians of 21 batches.\n\n| layout | resolution | cells | time per evaluation [us] | ns per cell | "
               "error in f, t |\n|---|---|---|---|---|---|\n");
    for (int L = 0; L < 2; L++)
        for (int k = 0; k < 6; k++) {
            sf_contact_spec spec = { R, N, L ? SF_LAYOUT_CARTESIAN : SF_LAYOUT_POLAR, cells[L][k] };
            sf_contact *c;
            sf_contact_alloc(&spec, grid, &c);
            double q[3], u = eps * w * R;
            sf_contact_wrench(c, 0, 0, u, 0, w, 1, q);
            err[L][k] = fmax(fabs(hypot(q[0], q[1]) / (0.5 * N) - fe), fabs(fabs(q[2]) / (0.5 * N * R) - te));
            size_t reps = 1 + 2000000 / sf_contact_ncells(c);
            double t[21];
            for (int b = 0; b < 21; b++) {
                double t0 = now();
                for (size_t i = 0; i < reps; i++)
                    sf_contact_wrench(c, 1e-3 * (double)i, 0, u, 0, w, 1, q);
                t[b] = (now() - t0) / (double)reps;
            }
            gsl_sort(t, 1, 21);
            cost[L][k] = t[10];
            npts[L][k] = (double)sf_contact_ncells(c);
            fprintf(f, "| %s | %zu | %zu | %.3f | %.2f | %.2e |\n", L ? "Cartesian" : "polar", cells[L][k],
                    sf_contact_ncells(c), 1e6 * cost[L][k], 1e9 * cost[L][k] / npts[L][k], err[L][k]);
            sf_contact_free(c);
        }
    sf_cof_free(grid);
    sf_result *r = sf_result_alloc();
    sf_plot *p = sf_result_plot(r, "wrench_work_precision", "Friction wrench: error vs cost per evaluation",
                                "time per evaluation [s]", "error in f, t vs closed form [-]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "polar (Gauss radii)", SF_STYLE_LINESPOINTS, 6, cost[0], err[0]);
    sf_plot_series(p, "Cartesian (cut cells)", SF_STYLE_LINESPOINTS, 6, cost[1], err[1]);
    char e[200];
    int rc = sf_result_render_plots(r, dir, e, sizeof e);
    sf_result_free(r);
    fprintf(f, "\n![Friction wrench work-precision](wrench_work_precision.png)\n\nAt equal error the polar layout "
               "needs far fewer cells (its radii are Gauss points; the Cartesian rim is first-order cut cells). "
               "The dynamics defaults to polar.\n");
    return rc ? 1 : 0;
}
