/* Checks of the tiled belt COF along a run (docs/design.md sec. 4.3): the window
 * follows the disc in bounded memory, every look-up lands on it, and the
 * field it shows is one field (random access); the same bits for any
 * thread count. */
#include "checks.h"
#include "common.h"
#include "cof.h"
#include "oscillator.h"
#include "sf_error.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A run at small l with the tiled generator: memory, coverage, random access. */
static int chk_tiles_window(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    char err[256] = "";
    sf_cof_plan *p;
    if (sf_cof_plan_alloc(s, &p, err, sizeof err)) {
        sf_note(r, "**The COF plan was refused:** %s", err);
        return SF_EFAIL;
    }
    const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
    int tiles = in->kind == SF_COF_FIELD && in->generator == SF_COFGEN_TILES;
    sf_check_true(r, "the plan chose the tiled generator", tiles, tiles ? "tiles" : "not tiles");
    double strip_points = in->strip_points;
    gsl_rng *rng = sf_case_rng(c), *rng2 = gsl_rng_clone(rng);
    sf_cof *cof = NULL, *cof2 = NULL;
    int rc = sf_cof_plan_draw(p, rng, &cof);
    if (!rc)
        rc = sf_cof_plan_draw(p, rng2, &cof2);   /* the same realisation, drawn again */
    sf_cof_plan_free(p);
    gsl_rng_free(rng);
    gsl_rng_free(rng2);
    if (rc || !tiles) {
        sf_cof_free(cof);
        sf_cof_free(cof2);
        return SF_EFAIL;
    }
    check_hist h = { .every = 1 };
    sf_osc_result res;
    rc = check_osc_run(s, NULL, cof, 0, &res, check_hist_row, &h, r);
    if (rc) {
        check_hist_free(&h);
        sf_cof_free(cof);
        sf_cof_free(cof2);
        return SF_EFAIL;
    }
    size_t m, n, m2, n2;
    double x0, y0, dx, dy, x02, y02, dx2, dy2;
    const double *g = NULL, *g2 = NULL;
    if (sf_cof_grid_view(cof, &m, &n, &x0, &y0, &dx, &dy, &g)) {   /* a tiled COF is always a grid */
        sf_note(r, "**The run's COF is not a grid.**");
        check_hist_free(&h);
        sf_osc_result_free(&res);
        sf_cof_free(cof);
        sf_cof_free(cof2);
        return SF_EFAIL;
    }
    double held = (double)sf_cof_points_held(cof);
    /* the bound from the disc's geometry alone: at most 4R of belt along x
     * (footprint 2R plus margins and slack) over the strip's width */
    double W = s->strip_halfwidth + s->R, bound = (ceil(4 * s->R / dx) + 2) * (ceil(2 * W / dy) + 4);
    sf_check_le(r, "grid points held by the window [-]", held, bound);
    sf_check_le(r, "look-ups off the window during the run (every stage, rejected ones included)",
                (double)sf_cof_outside(cof), 0);
    sf_check_le(r, "accepted states whose contact patch left the window", (double)res.off_strip, 0);
    double travel = s->v_b * s->T, wlen = dx * (double)(m - 1);
    int slid = sf_cof_slides(cof) >= 1 && travel > wlen;
    char found[160];
    snprintf(found, sizeof found, "%lu slides; belt travel %.3g m vs window %.3g m", sf_cof_slides(cof), travel, wlen);
    sf_check_true(r, "the belt travelled farther than the window is long, and the window slid", slid, found);
    /* random access: the same realisation drawn again, sent far away and
     * then to the final window (each a whole fill: no column carried over)
     * holds the same bits */
    rc = sf_cof_follow(cof2, x0 - 3 * wlen, x0 - 3 * wlen + dx);
    if (!rc)
        rc = sf_cof_follow(cof2, x0 + 2 * s->R, x0 + 2 * s->R + dx);
    if (!rc)
        rc = sf_cof_grid_view(cof2, &m2, &n2, &x02, &y02, &dx2, &dy2, &g2);
    long off = lround((x0 - x02) / dx);   /* window 1 column i is window 2 column i + off */
    size_t cmp = 0, diff = 0;
    for (size_t j = 0; j < n && !rc; j++)
        for (size_t i = 0; i < m; i++) {
            long i2 = (long)i + off;
            if (i2 < 0 || i2 >= (long)m2)
                continue;
            cmp++;
            diff += memcmp(&g[i + m * j], &g2[(size_t)i2 + m2 * j], sizeof *g) != 0;
        }
    snprintf(found, sizeof found, "%zu values compared, %zu differ", cmp, diff);
    sf_check_true(r, "the final window vs the same realisation made afresh there (whole fills): the same bits",
                  !rc && cmp > m * n / 2 && diff == 0, found);
    /* T = 12 s holds one stick cycle but not two maxima of x: the per-cycle PVs and the window's T_sk */
    int finite = isfinite(res.cyc_pv_x) && isfinite(res.cyc_pv_F) && isfinite(res.stick_fraction) && res.ncycles >= 1;
    sf_check_true(r, "at least one complete cycle, finite per-cycle PVs and T_sk", finite, finite ? "yes" : "no");
    sf_note(r, "l = %g m (l/R = %g), lattice spacing %.4g m: window %zu x %zu = %.3g points (%.1f MB) against %.3g for "
               "the circulant strip over [0, T]; %lu slides, %zu lattice columns made (%.3g m of belt); %zu cycles, "
               "PV_x per cycle = %.4g m, %zu steps.\n",
            s->l, s->l / s->R, dx, m, n, held, held * 8e-6, strip_points, sf_cof_slides(cof), sf_cof_columns_made(cof),
            (double)sf_cof_columns_made(cof) * dx, res.ncycles, res.cyc_pv_x, res.steps);
    /* plot: the disc's belt coordinate against time, with the window's final span */
    double *xb = check_alloc(h.n * sizeof *xb), *lo = check_alloc(h.n * sizeof *lo), *hi = check_alloc(h.n * sizeof *hi);
    for (size_t k = 0; k < h.n; k++) {
        xb[k] = h.x[k] - s->v_b * h.t[k];
        lo[k] = xb[k] - s->R;
        hi[k] = xb[k] + s->R;
    }
    sf_plot *pl = sf_result_plot(r, "belt_path", "The disc's footprint on the belt over the run", "t [s]",
                                 "belt coordinate x_b [m]");
    sf_plot_band(pl, "footprint x_b +- R", h.n, h.t, lo, hi);
    sf_plot_series(pl, "centre x_b = x - v_b t", SF_STYLE_LINES, h.n, h.t, xb);
    sf_plot_hline(pl, "final window, low edge", x0);
    sf_plot_hline(pl, "final window, high edge", x0 + wlen);
    free(xb); free(lo); free(hi);
    check_hist_free(&h);
    sf_osc_result_free(&res);
    sf_cof_free(cof);
    sf_cof_free(cof2);
    return SF_SUCCESS;
}

/* A Monte Carlo point with 1 and 2 threads: the same bits. */
static int chk_tiles_threads(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_sweep_point a, b;
    char err[256] = "";
    if (sf_sweep_run(s, s->samples, 1, NULL, 0, NULL, &a, err, sizeof err)) {
        sf_note(r, "**Sweep failed (1 thread):** %s", err);
        return SF_EFAIL;
    }
    if (sf_sweep_run(s, s->samples, 2, NULL, 0, NULL, &b, err, sizeof err)) {
        sf_note(r, "**Sweep failed (2 threads):** %s", err);
        sf_sweep_point_free(&a);
        return SF_EFAIL;
    }
    size_t n = a.n * SF_SWEEP_NQ;
    int same = a.n == b.n && !memcmp(a.ratio, b.ratio, n * sizeof *a.ratio);
    sf_check_true(r, "ratios of every realisation, 1 thread vs 2 threads (bytes)", same, same ? "identical" : "differ");
    int valid = a.n_valid == a.n;
    sf_check_true(r, "every realisation has a complete cycle (the ratios compared are numbers)", valid,
                  valid ? "all" : "some NaN");
    double *idx = check_alloc(a.n * sizeof *idx), *ya = check_alloc(a.n * sizeof *ya), *yb = check_alloc(a.n * sizeof *yb);
    for (size_t i = 0; i < a.n; i++) {
        idx[i] = (double)i;
        ya[i] = a.ratio[SF_SWEEP_NQ * i + SF_SWEEP_PVX];
        yb[i] = b.ratio[SF_SWEEP_NQ * i + SF_SWEEP_PVX];
    }
    sf_plot *pl = sf_result_plot(r, "ratios", "PV_x ratio per realisation, 1 and 2 threads", "realisation [-]",
                                 "PV_x / PV_x,det [-]");
    sf_plot_series(pl, "1 thread", SF_STYLE_POINTS, a.n, idx, ya);
    sf_plot_series(pl, "2 threads", SF_STYLE_POINTS, a.n, idx, yb);
    sf_note(r, "%zu realisations of the tiled field (l = %g m), each from its own stream (sf_mc_seed): the tiles' "
               "key is drawn from it, so a realisation's field does not depend on which thread runs it.\n",
            a.n, s->l);
    free(idx); free(ya); free(yb);
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_belt[] = {
    { "dyn_tiles_window", chk_tiles_window,
      "tiled COF along a run: bounded window, every look-up on it, random access" },
    { "dyn_tiles_threads", chk_tiles_threads, "tiled COF Monte Carlo: same bits with 1 and 2 threads" },
    { NULL, NULL, NULL }
};
