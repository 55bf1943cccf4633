/* slipfield field SCENE --samples N --out FILE: sample lognormal COF
 * fields on the scene's grid (nx x ny, dx, dy, l, mu_mean, mu_std). */
#include "cli.h"
#include "lnfield.h"
#include "sf_error.h"

#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_rng.h>

static void usage(FILE *f)
{
    fputs("usage: slipfield field SCENE [--samples N] [--out FILE]\n"
          "Sample lognormal COF random fields (circulant embedding + Nataf map).\n"
          "Writes TSV with header: sample x y gaussian cof (x, y in metres; gaussian\n"
          "is the standard normal field, cof the lognormal COF, dimensionless).\n"
          "  --samples N   number of fields (default: the scene's samples if it sets\n"
          "                the key, else 1)\n"
          "  --out FILE    output file, '-' for stdout (default)\n",
          f);
}

int sf_cmd_field(int argc, char **argv)
{
    const char *scene_path, *out_path = "-";
    size_t samples = 0;   /* 0: not given */
    const sf_opt opts[] = {
        { "--samples", SF_OPT_SIZE, &samples, 1, 1000000, NULL },
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
    };
    int rc = sf_cli_parse("field", argc, argv, opts, 2, &scene_path, usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    sf_scene s;
    if (sf_cli_load_scene("field", scene_path, &s))
        return SF_EXIT_USAGE;
    if (samples)
        sf_cli_key_overridden("field", scene_path, &s, "samples", "--samples");
    else
        samples = sf_scene_was_set(&s, "samples") ? s.samples : 1;
    sf_lnfield *lf;
    rc = sf_lnfield_alloc(&s, &lf);
    if (rc == SF_ETRUNC) {
        fprintf(stderr, "slipfield field: warning: embedding padding cap reached; covariance error %.3g\n",
                sf_field_get_info(sf_lnfield_gaussian(lf))->cov_error);
    } else if (rc) {
        fprintf(stderr, "slipfield field: %s: cannot build the field: %s\n", scene_path, sf_strerror(rc));
        return sf_cli_status(rc);
    }
    rc = SF_SUCCESS;   /* a truncated embedding is usable (warned above) */
    size_t n = s.nx * s.ny;
    double *g = malloc(n * sizeof *g), *h = malloc(n * sizeof *h);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_out o;
    int st = !g || !h || !rng ? SF_EXIT_INTERNAL : sf_cli_open("field", out_path, scene_path, &o);
    if (st) {
        free(g); free(h); gsl_rng_free(rng); sf_lnfield_free(lf);
        return st;
    }
    gsl_rng_set(rng, s.seed);
    fprintf(o.f, "sample\tx\ty\tgaussian\tcof\n");
    for (size_t k = 0; k < samples && !rc && !ferror(o.f); k++) {
        rc = sf_lnfield_sample(lf, rng, g, h);
        for (size_t j = 0; j < s.ny && !rc; j++)
            for (size_t i = 0; i < s.nx; i++)
                fprintf(o.f, "%zu\t%.10g\t%.10g\t%.17g\t%.17g\n", k, (double)i * s.dx,
                        (double)j * s.dy, g[i + s.nx * j], h[i + s.nx * j]);
    }
    free(g);
    free(h);
    gsl_rng_free(rng);
    sf_lnfield_free(lf);
    if (rc)
        fprintf(stderr, "slipfield field: %s: %s\n", scene_path, sf_strerror(rc));
    st = sf_cli_close("field", &o, !rc);
    return rc ? sf_cli_status(rc) : st;
}
