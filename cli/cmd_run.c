/* slipfield run SCENE [--out FILE] [--summary FILE] [--explain]
 *                     [--realisation I]: one realisation of the scene (COF
 * drawn from `seed`, or realisation I of a sweep of the scene: stream
 * sf_mc_stream(seed, I)), the time history as TSV and the quantities of
 * interest as `key = value` lines. */
#include "cli.h"
#include "cof.h"
#include "montecarlo.h"
#include "oscillator.h"
#include "sf_error.h"
#include "unum.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_rng.h>

static void usage(FILE *f)
{
    fputs("usage: slipfield run SCENE [--out FILE] [--summary FILE] [--explain]\n"
          "                           [--realisation I]\n"
          "Integrate the stick-slip oscillator over [0, T] for one COF realisation.\n"
          "  --out FILE      time history, TSV with header:\n"
          "                  t x y phi vx vy omega Fx Fy T state\n"
          "                  (s, m, m, rad, m/s, m/s, rad/s, N, N, N m, stick|slip);\n"
          "                  one row per accepted step and per event\n"
          "  --summary FILE  quantities of interest as `key = value` lines (pv_x, pv_F,\n"
          "                  stick_fraction, each with its realisations used and excluded,\n"
          "                  cycles, transitions, ...) and each QoI's numerical error\n"
          "                  u_num (u_pv_x, ...: a coarser companion solve of the same\n"
          "                  realisation, 0.04-0.45x the run's CPU); '-' for stdout\n"
          "                  (the default when neither --out nor --summary is given)\n"
          "  --explain       print what the plan computes and what it skips, then exit\n"
          "  --realisation I the field of realisation I (0 to 9999999) of `slipfield\n"
          "                  sweep` at this scene (its row I at a swept value: the same\n"
          "                  stream sf_mc_seed(seed, I), the same field bits), instead\n"
          "                  of the field the generator seeded with `seed` draws\n"
          "A run without --out keeps no history. T must be above t_skip (exit 2\n"
          "otherwise, as for sweep). A quantity that the run cannot form (no complete\n"
          "cycle after t_skip: raise T) is nan in the summary, and said on stderr.\n",
          f);
}

#define NO_REALISATION ((size_t)-1)

static void row_out(void *ctx, const sf_osc_row *r)
{
    fprintf(ctx, "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%s\n", r->t, r->x, r->y,
            r->phi, r->vx, r->vy, r->w, r->Fx, r->Fy, r->T, r->stick ? "stick" : "slip");
}

static void summary(FILE *f, const sf_scene *s, const sf_osc_result *r, size_t realisation)
{
    fprintf(f, "# slipfield run summary, from rest at the origin unless the scene says otherwise; window [t_skip, T]\n"
               "# qoi_def = %s: %s\n", s->qoi_def == SF_QOI_PAPER ? "paper" : "cycles",
            s->qoi_def == SF_QOI_PAPER ? "stick_fraction = stick time in the window / (T - t_skip) (paper Sec. 3.1); "
                                         "pv_x, pv_F = mean over the oscillations (maximum of x to the next), stick or not"
                                       : "stick_fraction, pv_x, pv_F over complete cycles (stick onset to stick onset, "
                                         "onset >= t_skip)");
    fprintf(f, "pv_x = %.17g\npv_F = %.17g\nstick_fraction = %.17g\nperiod = %.17g\n", r->pv_x, r->pv_F,
            r->stick_fraction, r->period);
    fprintf(f, "oscillations = %zu\nstick_time = %.17g\n", r->nosc, r->stick_time);
    /* one realisation: each QoI used (finite) or excluded (nothing to measure), as in a sweep's summary */
    const char *qn[3] = { "pv_x", "pv_F", "stick_fraction" };
    const double qv[3] = { r->pv_x, r->pv_F, r->stick_fraction };
    for (int q = 0; q < 3; q++)
        fprintf(f, "%s_n_used = %d\n%s_n_excluded = %d\n", qn[q], isfinite(qv[q]) != 0, qn[q], !isfinite(qv[q]));
    fprintf(f, "cycles = %zu\ntransitions = %zu\nbifurcation_samples = %zu\n", r->ncycles, r->ntrans, r->nbif);
    fprintf(f, "x_min = %.17g\nx_max = %.17g\ny_absmax = %.17g\n", r->x_min, r->x_max, r->y_absmax);
    fprintf(f, "energy_change = %.17g\nfriction_work = %.17g\njump_energy = %.17g\nenergy_residual = %.17g\n",
            r->energy_change, r->friction_work, r->jump_energy, r->energy_residual);
    fprintf(f, "steps = %lu\nrejected_steps = %lu\nbisection_steps = %lu\nwrench_evaluations = %lu\n", r->steps,
            r->rejected, r->event_trials, r->wrench_evals);
    fprintf(f, "t_skip = %.17g\nT = %.17g\nseed = %lu\n", s->t_skip, s->T, s->seed);
    if (realisation != NO_REALISATION)   /* the sweep's stream of it */
        fprintf(f, "realisation = %zu\nstream_seed = %lu\n", realisation, sf_mc_seed(s->seed, realisation));
}

int sf_cmd_run(int argc, char **argv)
{
    const char *path, *out_path = NULL, *sum_path = NULL;
    int explain = 0;
    size_t realisation = NO_REALISATION;
    const sf_opt opts[] = {
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
        { "--summary", SF_OPT_STRING, &sum_path, 0, 0, NULL },
        { "--explain", SF_OPT_FLAG, &explain, 0, 0, NULL },
        { "--realisation", SF_OPT_SIZE, &realisation, 0, 9999999, NULL },
    };
    int rc = sf_cli_parse("run", argc, argv, opts, sizeof opts / sizeof opts[0], &path, usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    if (!out_path && !sum_path)
        sum_path = "-";
    sf_scene s;
    if (sf_cli_load_scene("run", path, &s))
        return SF_EXIT_USAGE;
    if (!(s.T > s.t_skip)) {   /* the same refusal as slipfield sweep's */
        fprintf(stderr, "slipfield run: %s: T = %g s is not above t_skip = %g s: no cycle to measure (raise T or lower "
                        "t_skip)\n", path, s.T, s.t_skip);
        return SF_EXIT_USAGE;
    }
    if (out_path && !s.history) {
        fprintf(stderr, "slipfield run: %s: the scene sets history = false; drop --out or the key\n", path);
        return SF_EXIT_USAGE;
    }
    char err[256] = "";
    sf_plan pl;   /* the run's plan, made first: the builders below take it */
    sf_cof_plan *plan = NULL;
    if ((rc = sf_plan_make(&s, &pl, err, sizeof err)) || (rc = sf_cof_plan_build(&s, &pl, &plan, err, sizeof err))) {
        fprintf(stderr, "slipfield run: %s: %s\n", path, *err ? err : sf_strerror(rc));
        return sf_cli_status(rc);
    }
    sf_cli_warn_truncated("run", path, &s, plan);
    pl.history = out_path != NULL;   /* without --out, only the QoIs */
    if (explain) {
        printf("plan for %s (shortcuts %s)\n", path, s.shortcuts ? "on" : "off: everything computed in full");
        sf_plan_explain(&pl, &s, stdout);
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (realisation == NO_REALISATION)
        gsl_rng_set(rng, s.seed);
    else
        sf_mc_stream(rng, s.seed, realisation);   /* as sf_mc_run seeds the sweep's realisation */
    sf_cof *cof = NULL;
    rc = sf_cof_plan_draw(plan, rng, &cof);
    gsl_rng_free(rng);
    sf_cof_plan_free(plan);
    sf_osc *o = NULL;
    if (rc || (rc = sf_osc_alloc_plan(&s, &pl, cof, &o, err, sizeof err))) {
        fprintf(stderr, "slipfield run: %s: %s\n", path, *err ? err : sf_strerror(rc));
        sf_cof_free(cof);
        return sf_cli_status(rc);
    }
    if (explain) {
        printf("set-up:\n");
        sf_osc_describe(o, stdout);
        sf_osc_free(o);
        sf_cof_free(cof);
        return SF_EXIT_OK;
    }
    if (*pl.num.warning)
        fprintf(stderr, "slipfield run: %s: warning: %s\n", path, pl.num.warning);
    sf_out out = { 0 }, sum = { 0 };
    int st = out_path ? sf_cli_open("run", out_path, path, &out) : SF_EXIT_OK;
    if (!st && sum_path && (st = sf_cli_open("run", sum_path, path, &sum)) && out_path)
        sf_cli_close("run", &out, 0);
    if (st) {
        sf_osc_free(o);
        sf_cof_free(cof);
        return st;
    }
    if (out_path)
        fprintf(out.f, "t\tx\ty\tphi\tvx\tvy\tomega\tFx\tFy\tT\tstate\n");
    sf_osc_result res;
    rc = sf_osc_run(o, out_path ? row_out : NULL, out.f, 0, &res, err, sizeof err);
    if (rc)
        fprintf(stderr, "slipfield run: %s: %s\n", path, *err ? err : sf_strerror(rc));
    else if (sum_path) {
        summary(sum.f, &s, &res, realisation);
        sf_unum u;   /* the numerical error of each QoI: a coarser companion solve (unum.h) */
        if ((rc = sf_unum_estimate(&s, cof, sf_osc_get_plan(o), &res, &u, err, sizeof err)))
            fprintf(stderr, "slipfield run: %s: the error estimate's companion solve: %s\n", path,
                    *err ? err : sf_strerror(rc));
        else
            sf_unum_write(&u, sum.f);
    }
    if (!rc && !(isfinite(res.pv_x) && isfinite(res.pv_F) && isfinite(res.stick_fraction)))
        fprintf(stderr, "slipfield run: %s: warning: no quantity of interest: %zu complete cycles after t_skip = %g s "
                        "(pv_x, pv_F or stick_fraction is nan): raise T (%g s)\n",
                path, res.ncycles, s.t_skip, s.T);
    if (out_path && sf_cli_close("run", &out, rc == SF_SUCCESS) && !rc)
        st = SF_EXIT_USAGE;
    if (sum_path && sf_cli_close("run", &sum, rc == SF_SUCCESS) && !rc)
        st = SF_EXIT_USAGE;
    sf_osc_result_free(&res);
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc ? sf_cli_status(rc) : st;
}
