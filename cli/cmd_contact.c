/* slipfield surface / wrench: the contact module from the command line.
 *   surface SCENE --out FILE   Eq. 11 on the scene's (ntheta x npsi) grid
 *   wrench SCENE --vx --vy --spin [--xb --yb]   Eqs. 7-8 at one motion
 * Both use the scene's COF model (uniform, one random variable, or the
 * lognormal field on the belt strip; realisation drawn from `seed`) and
 * its quadrature (layout, cells). */
#include "cli.h"
#include "cof.h"
#include "contact.h"
#include "numplan.h"
#include "surface.h"
#include "sf_error.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

typedef struct {
    sf_cof *cof;
    sf_contact *ct;
} contact_run;

/* The scene's COF (one realisation) and quadrature; prints the reason on
 * failure. */
static int contact_open(const char *cmd, const char *path, const sf_scene *s, contact_run *cr)
{
    cr->cof = NULL;
    cr->ct = NULL;
    char err[256] = "";
    sf_cof_plan *p;
    int rc = sf_cof_plan_alloc(s, &p, err, sizeof err);
    if (rc) {
        fprintf(stderr, "slipfield %s: %s: %s\n", cmd, path, *err ? err : sf_strerror(rc));
        return sf_cli_status(rc);
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, s->seed);
    rc = sf_cof_plan_draw(p, rng, &cr->cof);
    gsl_rng_free(rng);
    sf_cof_plan_free(p);
    sf_numplan np;   /* cells = 0: the plan's resolution, as a run would use */
    if (!rc)
        rc = sf_numplan_make(s, 1, &np, err, sizeof err);
    sf_contact_spec spec = { s->R, s->m * s->g, (sf_layout)s->layout, rc ? s->cells : np.cells };
    if (!rc)
        rc = sf_contact_alloc(&spec, cr->cof, &cr->ct);
    if (rc) {
        fprintf(stderr, "slipfield %s: %s: cannot set up the contact: %s\n", cmd, path, *err ? err : sf_strerror(rc));
        sf_cof_free(cr->cof);
        return sf_cli_status(rc);
    }
    return SF_EXIT_OK;
}

static void contact_close(contact_run *cr)
{
    sf_contact_free(cr->ct);
    sf_cof_free(cr->cof);
}

static void surface_usage(FILE *f)
{
    fputs("usage: slipfield surface SCENE [--out FILE] [--xb XB] [--yb YB]\n"
          "The static limit surface of Eq. 11 for the disc centred over belt point\n"
          "(XB, YB) [m] (default 0, 0), on the scene's direction grid: theta in\n"
          "[-pi/2, pi/2] (ntheta points), psi in [0, 2 pi) (npsi points).\n"
          "Writes TSV with header: theta psi Fx Fy T (angles in rad; Fx = F*x = Fx/N,\n"
          "Fy = Fy/N, T = T/(N R): dimensionless, N = m g).\n"
          "  --out FILE   output file, '-' for stdout (default)\n",
          f);
}

int sf_cmd_surface(int argc, char **argv)
{
    const char *path, *out_path = "-";
    double xb = 0, yb = 0;
    const sf_opt opts[] = {
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
        { "--xb", SF_OPT_DOUBLE, &xb, 0, 0, NULL },
        { "--yb", SF_OPT_DOUBLE, &yb, 0, 0, NULL },
    };
    int rc = sf_cli_parse("surface", argc, argv, opts, 3, &path, surface_usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    sf_scene s;
    if (sf_cli_load_scene("surface", path, &s))
        return SF_EXIT_USAGE;
    if (s.ntheta < 2) {
        fprintf(stderr, "slipfield surface: %s: ntheta must be at least 2 (both poles)\n", path);
        return SF_EXIT_USAGE;
    }
    contact_run cr;
    if ((rc = contact_open("surface", path, &s, &cr)))
        return rc;
    sf_surface *sf;
    sf_out o;
    if ((rc = sf_surface_alloc(cr.ct, xb, yb, &sf))) {
        fprintf(stderr, "slipfield surface: %s: %s\n", path, sf_strerror(rc));
        contact_close(&cr);
        return sf_cli_status(rc);
    }
    if ((rc = sf_cli_open("surface", out_path, path, &o))) {
        sf_surface_free(sf);
        contact_close(&cr);
        return rc;
    }
    fprintf(o.f, "theta\tpsi\tFx\tFy\tT\n");
    for (size_t i = 0; i < s.ntheta && !ferror(o.f); i++)
        for (size_t j = 0; j < s.npsi; j++) {
            double th = -M_PI / 2 + M_PI * (double)i / (double)(s.ntheta - 1);
            double ps = 2 * M_PI * (double)j / (double)s.npsi, q[3];
            sf_surface_point(sf, th, ps, q);
            fprintf(o.f, "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", th, ps, q[0], q[1], q[2]);
        }
    sf_surface_free(sf);
    contact_close(&cr);
    return sf_cli_close("surface", &o, 1);
}

static void wrench_usage(FILE *f)
{
    fputs("usage: slipfield wrench SCENE [--vx VX] [--vy VY] [--spin W] [--xb XB] [--yb YB] [--out FILE]\n"
          "The friction wrench of the belt on the disc (Eqs. 7-8), static COF.\n"
          "  --vx, --vy   disc centre velocity in the ground frame [m/s]; the slip\n"
          "               relative to the belt is (VX - v_b, VY) (default: the\n"
          "               scene's relative velocity u, v)\n"
          "  --spin W     disc spin rate [rad/s] (default: the scene's w)\n"
          "  --xb, --yb   belt point under the disc centre [m] (default 0, 0)\n"
          "  --kinetic    use the kinetic COF (mu_k_ratio x static)\n"
          "  --out FILE   output, '-' for stdout (default)\n"
          "Prints a header line and one line: Fx [N], Fy [N], T [N m].\n",
          f);
}

int sf_cmd_wrench(int argc, char **argv)
{
    const char *path, *out_path = "-";
    double vx = NAN, vy = NAN, w = NAN, xb = 0, yb = 0;
    int kinetic = 0;
    const sf_opt opts[] = {
        { "--vx", SF_OPT_DOUBLE, &vx, 0, 0, NULL },
        { "--vy", SF_OPT_DOUBLE, &vy, 0, 0, NULL },
        { "--spin", SF_OPT_DOUBLE, &w, 0, 0, NULL },
        { "--xb", SF_OPT_DOUBLE, &xb, 0, 0, NULL },
        { "--yb", SF_OPT_DOUBLE, &yb, 0, 0, NULL },
        { "--kinetic", SF_OPT_FLAG, &kinetic, 0, 0, NULL },
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
    };
    int rc = sf_cli_parse("wrench", argc, argv, opts, 7, &path, wrench_usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    sf_scene s;
    if (sf_cli_load_scene("wrench", path, &s))
        return SF_EXIT_USAGE;
    /* a flag given overrides the scene's key; a key not overridden is used */
    const struct { double *flag, key; const char *name, *opt; } motion[] = {
        { &vx, s.u + s.v_b, "u", "--vx" }, { &vy, s.v, "v", "--vy" }, { &w, s.w, "w", "--spin" },
    };
    for (size_t k = 0; k < 3; k++) {
        if (isnan(*motion[k].flag))
            *motion[k].flag = motion[k].key;
        else
            sf_cli_key_overridden("wrench", path, &s, motion[k].name, motion[k].opt);
    }
    contact_run cr;
    if ((rc = contact_open("wrench", path, &s, &cr)))
        return rc;
    double q[3];
    rc = sf_contact_wrench(cr.ct, xb, yb, vx - s.v_b, vy, w, kinetic ? s.mu_k_ratio : 1.0, q);
    contact_close(&cr);
    if (rc) {
        fprintf(stderr, "slipfield wrench: %s: %s\n", path, sf_strerror(rc));
        return sf_cli_status(rc);
    }
    sf_out o;
    if ((rc = sf_cli_open("wrench", out_path, path, &o)))
        return rc;
    fprintf(o.f, "Fx\tFy\tT\n%.17g\t%.17g\t%.17g\n", q[0], q[1], q[2]);
    return sf_cli_close("wrench", &o, 1);
}
