/* libslipfield: the paper's Table 1 oscillator on a uniform COF, simulated
 * and checked against the closed-form stick-slip cycle.  Build it with
 *   cc -std=c11 cycle.c $(pkg-config --cflags --libs slipfield) -o cycle */
#include <slipfield/cof.h>
#include <slipfield/cycle1d.h>
#include <slipfield/oscillator.h>
#include <slipfield/sf_error.h>
#include <math.h>
#include <stdio.h>

int main(void)
{
    sf_scene s;
    sf_cof *cof = NULL;
    sf_osc *osc = NULL;
    sf_osc_result res = { 0 };
    sf_cycle1d cf;
    char err[256] = "";
    sf_init();               /* once, first: GSL errors are returned, not abort()ed on */
    sf_scene_default(&s);    /* Table 1: m = 10 kg, k = 30 N/m, v_b = 0.2 m/s, ... */
    if (sf_scene_parse(&s, "cof = uniform\ndof = 1\nrtol = 1e-10\nT = 60\nt_skip = 10\n", "example", 1, err, sizeof err) ||
        sf_cof_alloc_uniform(s.mu_mean, &cof) || sf_osc_alloc(&s, cof, &osc, err, sizeof err) ||
        sf_osc_run(osc, NULL, NULL, 0, &res, err, sizeof err) || sf_cycle1d_init(&cf, &s, s.eps_lambda))
        return fprintf(stderr, "cycle: failed %s\n", err), 1;
    printf("PV_x: simulated %.6f m, closed form %.6f m (%zu cycles)\n", res.pv_x, cf.pv_x, res.ncycles);
    int ok = fabs(res.pv_x - cf.pv_x) <= 1e-6 * cf.pv_x;   /* rtol 1e-10: well inside */
    sf_osc_result_free(&res);
    sf_osc_free(osc);
    sf_cof_free(cof);
    return ok ? 0 : 1;
}
