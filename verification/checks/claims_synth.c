/* The claims engine checked on synthetic claims of known truth: its
 * verdict rule (claims_decide, what claims_judge_one and the sweep's
 * judgement call) and each test's alpha (claims_alpha: the case's alpha /
 * the claims / the looks), with no solve.  Estimates are drawn from laws
 * whose truth is planted (on a claim's boundary, at its minimum detectable
 * effect, at half of it), and the rate of each verdict over many
 * replications is tested against the rate the engine states with an
 * exact binomial test (cases/validation/claims-engine-synthetic.md). */
#include "checks.h"
#include "common.h"
#include "claims_engine.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

/* The synthetic case the engine judges: alpha SYN_ALPHA over SYN_LOOKS
 * looks and the three claims below, so each test runs at SYN_ALPHA / 3 /
 * SYN_LOOKS = 0.01 and a claim's share over the looks is 0.02. */
#define SYN_ALPHA 0.06
#define SYN_LOOKS 2
#define SYN_N 5          /* realisations a look (Student t on 4 df) */
#define SYN_SIGMA 1.0    /* their standard deviation; the claims' thresholds at 0 */
#define SYN_EQ_HI 10.0   /* the equivalence margin [0, 10]: its upper side never binds at the boundary 0 */

static const claim_spec syn_claims[] = {
    { "syn-up", "the statistic exceeds 0", K_MEAN, Q_PVX, "=1", NULL, 0, 0, +1, 'D', 'D', NULL, NULL },
    { "syn-down", "the statistic is below 0", K_MEAN, Q_PVX, "=1", NULL, 0, 0, -1, 'D', 'D', NULL, NULL },
    { "syn-eq", "the statistic lies in [0, 10]", K_MEAN_EQ, Q_PVX, "=1", NULL, 0, SYN_EQ_HI, 0, 'D', 'D', NULL, NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};

/* the mean and its standard error of n values */
static void mean_se(const double *x, size_t n, double *m, double *se)
{
    double s = 0, ss = 0;
    for (size_t i = 0; i < n; i++)
        s += x[i];
    *m = s / (double)n;
    for (size_t i = 0; i < n; i++)
        ss += (x[i] - *m) * (x[i] - *m);
    *se = sqrt(ss / (double)(n - 1) / (double)n);
}

/* exact binomial p-values of k successes in R at rate p0 */
static double p_upper(unsigned k, double p0, unsigned R) { return k ? gsl_cdf_binomial_Q(k - 1, p0, R) : 1; }
static double p_lower(unsigned k, double p0, unsigned R) { return gsl_cdf_binomial_P(k, p0, R); }
static double p_two(unsigned k, double p0, unsigned R)
{
    double p = 2 * fmin(p_upper(k, p0, R), p_lower(k, p0, R));
    return p < 1 ? p : 1;
}

/* the smallest count an upper test at level a rejects, and its power at p1 */
static unsigned crit_upper(double p0, unsigned R, double a)
{
    unsigned k = 0;
    while (k <= R && p_upper(k, p0, R) >= a)
        k++;
    return k;
}
/* its type-II error: the chance a defect's rate p1 stays below it */
static double miss_upper(double p0, double p1, unsigned R, double a)
{
    unsigned k = crit_upper(p0, R, a);
    return k ? gsl_cdf_binomial_P(k - 1, p1, R) : 0;
}

/* The sequential design of the verdicts about the model
 * (claims_sequential_decide): syn-up with an indifference margin SEQ_M,
 * looks at SEQ_N1, 2 SEQ_N1, ... SEQ_BUDGET values (each extending the
 * last), the model share SEQ_ALPHA spent over them (Pocock-type), the
 * normal path (sigma known: se = 1 / sqrt(n)). */
#define SEQ_N1 5
#define SEQ_BUDGET 40
#define SEQ_M 1.0
#define SEQ_ALPHA 0.02

/* the truths planted: none (0), half the margin, the margin, minus the margin */
enum { T_NONE, T_HALF, T_MARGIN, T_NEG, NT };

enum { R_UP_CONF, R_UP_CONTRA, R_DN_CONF, R_DN_CONTRA, R_EQ_CONF, R_DESIGN, R_POWER, R_HALF,
       S_NONE_CONF, S_NONE_CONTRA, S_NONE_WITHIN, S_HALF_CONTRA, S_HALF_RIGHT, S_MARGIN_CONF, S_MARGIN_WITHIN,
       S_NEG_CONTRA, S_NEG_WITHIN, NR };
/* a sequential row that counts a right verdict (at least its bound; the others count a wrong one) */
static int seq_right(int j)
{
    return j == S_NONE_WITHIN || j == S_HALF_RIGHT || j == S_MARGIN_CONF || j == S_NEG_CONTRA;
}

/* One run of the design at truth theta: values drawn one look at a time
 * (look j's sample extends look j-1's); the verdict, the look into *look.
 * naive: every look at the whole share (the boundary that ignores the
 * number of looks; reported, not gated). */
static int seq_run(gsl_rng *g, double theta, const size_t *N, size_t L, int naive, size_t *look)
{
    double est[CLAIMS_MAX_LOOKS], se[CLAIMS_MAX_LOOKS], df[CLAIMS_MAX_LOOKS], sum = 0;
    size_t n = 0;
    *look = L - 1;
    for (size_t j = 0; j < L; j++) {
        for (; n < N[j]; n++)
            sum += theta + gsl_ran_gaussian(g, 1);
        est[j] = sum / (double)n;
        se[j] = 1 / sqrt((double)n);
        df[j] = 1e9;
        int st = naive ? claims_sequential_decide(&syn_claims[0], N + j, 1, 1, est + j, se + j, df + j, SEQ_ALPHA,
                                                  SEQ_M, 0, CLAIMS_SPEND_POCOCK, NULL, NULL, NULL)
                       : claims_sequential_decide(&syn_claims[0], N, L, j + 1, est, se, df, SEQ_ALPHA, SEQ_M, 0,
                                                  CLAIMS_SPEND_POCOCK, NULL, NULL, NULL);
        if (st != SF_CLAIM_UNDECIDED) {
            *look = j;
            return st;
        }
    }
    return SF_CLAIM_UNDECIDED;
}

static int chk_claims_synth(const sf_case *c, sf_result *r)
{
    unsigned R = (unsigned)c->scene.samples;
    if (R < 100)
        return SF_EINVAL;
    double level = c->spec.alpha / NR;   /* each binomial test (Bonferroni over the rows) */
    sf_case *syn = check_alloc(sizeof *syn);
    *syn = *c;
    syn->spec.alpha = SYN_ALPHA;
    syn->spec.looks = SYN_LOOKS;
    /* the engine's alpha a test (what it judges at), and the rates its
     * design promises, from the synthetic case's definition: a test at
     * alpha / claims / looks, a claim over the looks at alpha / claims */
    double a = claims_alpha(syn, syn_claims);
    double p_test = SYN_ALPHA / 3 / SYN_LOOKS, share = SYN_ALPHA / 3;
    free(syn);
    const claim_spec *up = &syn_claims[0], *dn = &syn_claims[1], *eq = &syn_claims[2];
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, c->scene.seed);
    double *est0 = check_alloc(R * sizeof *est0), *est2 = check_alloc(R * sizeof *est2),
           *estp = check_alloc(R * sizeof *estp), *esth = check_alloc(R * sizeof *esth);
    unsigned k[NR] = { 0 };
    /* (c) no effect: every claim's truth on its boundary 0, the t path
     * (df = n - 1): est / se is exactly Student t on 4 df, so each verdict
     * of each one-sided test occurs at exactly the test's alpha */
    for (unsigned i = 0; i < R; i++) {
        double x[2 * SYN_N], m, se;
        for (int j = 0; j < SYN_N; j++)
            x[j] = gsl_ran_gaussian(g, SYN_SIGMA);
        mean_se(x, SYN_N, &m, &se);
        est0[i] = m;
        int su = claims_decide(up, m, se, SYN_N - 1, a, NULL, NULL);
        int sd = claims_decide(dn, m, se, SYN_N - 1, a, NULL, NULL);
        k[R_UP_CONF] += su == SF_CLAIM_CONFIRMED;
        k[R_UP_CONTRA] += su == SF_CLAIM_CONTRADICTED;
        k[R_DN_CONF] += sd == SF_CLAIM_CONFIRMED;
        k[R_DN_CONTRA] += sd == SF_CLAIM_CONTRADICTED;
        k[R_EQ_CONF] += claims_decide(eq, m, se, SYN_N - 1, a, NULL, NULL) == SF_CLAIM_CONFIRMED;
        /* the group-sequential design on fresh values: look 1 at N, look 2
         * at 2N (look 1's and N more), stopping at the first decided look;
         * a wrong verdict of syn-up at either look counts once */
        for (int j = 0; j < 2 * SYN_N; j++)
            x[j] = gsl_ran_gaussian(g, SYN_SIGMA);
        int wrong = 0;
        for (int look = 1; look <= SYN_LOOKS; look++) {
            size_t n = (size_t)look * SYN_N;
            mean_se(x, n, &m, &se);
            int s = claims_decide(up, m, se, (double)n - 1, a, NULL, NULL);
            wrong = s == SF_CLAIM_CONFIRMED;
            if (s != SF_CLAIM_UNDECIDED)
                break;
        }
        est2[i] = m;
        k[R_DESIGN] += (unsigned)wrong;
    }
    /* (a), (b): a planted effect at the minimum detectable effect the
     * engine states (power CLAIM_MDE_POWER) and at half of it, on the
     * normal path (df above 1e6, the path of the engine's log-std, gap and
     * drop tests): est ~ N(effect, se^2) with se known, so the power is
     * exactly 0.99 at the MDE and Phi(MDE / 2 / se - z_alpha) at half */
    double se = 1, z = gsl_cdf_ugaussian_Qinv(p_test);
    double mde = (z + gsl_cdf_ugaussian_Qinv(1 - CLAIM_MDE_POWER)) * se;   /* at the promised alpha */
    double p_half = gsl_cdf_ugaussian_P(mde / 2 / se - z), mde_engine = claims_mde(se, a, 0);
    for (unsigned i = 0; i < R; i++) {
        estp[i] = mde + gsl_ran_gaussian(g, se);
        esth[i] = mde / 2 + gsl_ran_gaussian(g, se);
        k[R_POWER] += claims_decide(up, estp[i], se, 1e9, a, NULL, NULL) == SF_CLAIM_CONFIRMED;
        k[R_HALF] += claims_decide(up, esth[i], se, 1e9, a, NULL, NULL) == SF_CLAIM_CONFIRMED;
    }
    /* the sequential design at each planted truth; the stated rates: a
     * wrong verdict at most the share SEQ_ALPHA (the union bound over the
     * looks), a right one at least its test's power at the last look less
     * the wrong verdicts that could stop the design before it */
    size_t N[CLAIMS_MAX_LOOKS], L = claims_model_looks(SEQ_N1, SEQ_BUDGET, N);
    const double theta[NT] = { 0, SEQ_M / 2, SEQ_M, -SEQ_M };
    unsigned vc[NT][4] = { { 0 } }, naive_conf = 0;
    double nlook[NT] = { 0 };
    for (int t = 0; t < NT; t++)
        for (unsigned i = 0; i < R; i++) {
            size_t look;
            int st = seq_run(g, theta[t], N, L, 0, &look);
            vc[t][st]++;
            nlook[t] += (double)N[look];
        }
    for (unsigned i = 0; i < R; i++) {
        size_t look;
        naive_conf += seq_run(g, 0, N, L, 1, &look) == SF_CLAIM_CONFIRMED;
    }
    gsl_rng_free(g);
    double asum = 0, aj[CLAIMS_MAX_LOOKS];
    for (size_t j = 0; j < L; j++)
        asum += aj[j] = claims_look_alpha(SEQ_ALPHA, N, L, j, CLAIMS_SPEND_POCOCK);
    double seL = 1 / sqrt((double)N[L - 1]), zL = gsl_cdf_ugaussian_Qinv(aj[L - 1]);
    /* the last look's tests: confirm (lo > 0) at the margin, TOST (both
     * bounds inside -+ m; the intersection exact while z se < m) */
    double pc_m = gsl_cdf_ugaussian_P(SEQ_M / seL - zL), pt0 = 2 * gsl_cdf_ugaussian_P(SEQ_M / seL - zL) - 1;
    double pt_half = gsl_cdf_ugaussian_P(0.5 * SEQ_M / seL - zL) + gsl_cdf_ugaussian_P(1.5 * SEQ_M / seL - zL) - 1;
    k[S_NONE_CONF] = vc[T_NONE][SF_CLAIM_CONFIRMED];
    k[S_NONE_CONTRA] = vc[T_NONE][SF_CLAIM_CONTRADICTED];
    k[S_NONE_WITHIN] = vc[T_NONE][SF_CLAIM_WITHIN];
    k[S_HALF_CONTRA] = vc[T_HALF][SF_CLAIM_CONTRADICTED];
    k[S_HALF_RIGHT] = vc[T_HALF][SF_CLAIM_CONFIRMED] + vc[T_HALF][SF_CLAIM_WITHIN];
    k[S_MARGIN_CONF] = vc[T_MARGIN][SF_CLAIM_CONFIRMED];
    k[S_MARGIN_WITHIN] = vc[T_MARGIN][SF_CLAIM_WITHIN];
    k[S_NEG_CONTRA] = vc[T_NEG][SF_CLAIM_CONTRADICTED];
    k[S_NEG_WITHIN] = vc[T_NEG][SF_CLAIM_WITHIN];
    sf_result_data(r, "the sequential design's mean N at each planted truth", NT, nlook);
    sf_result_data(r, "estimates at the boundary, one look", R, est0);
    sf_result_data(r, "estimates at the boundary, the design's stopping look", R, est2);
    sf_result_data(r, "estimates at the MDE", R, estp);
    sf_result_data(r, "estimates at half the MDE", R, esth);
    free(est0); free(est2); free(estp); free(esth);

    /* the rates the engine states, and the exact binomial power of each
     * upper test against a defect's rate */
    static const char *const what[NR] = {
        "syn-up confirmed at its boundary (one look)", "syn-up contradicted at its boundary (one look)",
        "syn-down confirmed at its boundary (one look)", "syn-down contradicted at its boundary (one look)",
        "syn-eq (equivalence) confirmed at its margin's boundary (one look)",
        "syn-up wrongly confirmed over the 2-look design", "syn-up confirmed at the MDE",
        "syn-up confirmed at half the MDE",
        "sequential, no effect: wrongly confirmed", "sequential, no effect: wrongly contradicted",
        "sequential, no effect: within margin", "sequential, half the margin: wrongly contradicted",
        "sequential, half the margin: confirmed or within margin",
        "sequential, effect of the margin: confirmed", "sequential, effect of the margin: wrongly within margin",
        "sequential, minus the margin: contradicted", "sequential, minus the margin: wrongly within margin" };
    double p0[NR] = { p_test, p_test, p_test, p_test, p_test, share, CLAIM_MDE_POWER, p_half,
                      SEQ_ALPHA, SEQ_ALPHA, pt0 - 2 * SEQ_ALPHA, SEQ_ALPHA, pt_half - SEQ_ALPHA,
                      pc_m - 2 * SEQ_ALPHA, SEQ_ALPHA, pc_m - 2 * SEQ_ALPHA, SEQ_ALPHA },
           rate[NR], xs[NR], lo[NR], hi[NR];
    unsigned kc1 = crit_upper(p_test, R, level), kc2 = crit_upper(share, R, level);
    double pw6 = miss_upper(p_test, 6 * p_test, R, level), pw2 = miss_upper(p_test, 2 * p_test, R, level),
           pwd6 = miss_upper(share, 6 * share, R, level), pwd15 = miss_upper(share, 1.5 * share, R, level);
    char tab[4096];
    size_t used = 0;
    for (int j = 0; j < NR; j++) {
        rate[j] = k[j] / (double)R;
        xs[j] = j + 1;
        double w = sqrt(p0[j] * (1 - p0[j]) / R), zz = gsl_cdf_ugaussian_Qinv(level);
        int low = j == R_POWER || (j >= S_NONE_CONF && seq_right(j));
        lo[j] = low ? p0[j] - zz * w : j == R_HALF ? p0[j] - gsl_cdf_ugaussian_Qinv(level / 2) * w : 0;
        hi[j] = low ? 1 : j == R_HALF ? p0[j] + gsl_cdf_ugaussian_Qinv(level / 2) * w : p0[j] + zz * w;
        used += (size_t)snprintf(tab + used, sizeof tab - used, "| %d | %s | %u | %.5f | %.5f |\n", j + 1, what[j],
                                 k[j], rate[j], p0[j]);
    }
    sf_note(r, "Synthetic case: alpha %g, %d looks, %zu claims: claims_alpha = %.4g a test (promised: %.4g), a "
               "claim's share over the looks %.4g. %u replications a row (seed %lu); each exact binomial test at %.3g (the case's alpha "
               "%g over %d rows). The MDE at se = 1: %.4f (power %.2f); at half of it the exact power is %.4f.\n\n"
               "| row | verdict | count | rate | stated rate |\n|---|---|---|---|---|\n%s\n"
               "Power of the one-look type-I rows (exact binomial: reject from %u of %u): 1 - %.2g against 6x the "
               "rate (the case's whole alpha), 1 - %.2g against 2x (the looks ignored); of the design's row (reject "
               "from %u): 1 - %.2g against 6x the share, 1 - %.2g against 1.5x.\n",
            SYN_ALPHA, SYN_LOOKS, (size_t)3, a, p_test, share, R, c->scene.seed, level, c->spec.alpha, NR, mde,
            CLAIM_MDE_POWER, p_half, tab, kc1, R, pw6, pw2, kc2, pwd6, pwd15);
    unsigned kcs = crit_upper(SEQ_ALPHA, R, level);
    double pn = naive_conf / (double)R, pwn = miss_upper(SEQ_ALPHA, fmax(pn, SEQ_ALPHA), R, level);
    sf_note(r, "\nSequential rows (9-17): the verdict about the model (claims_sequential_decide) on syn-up (> 0) with "
               "the indifference margin %g, looks at N = %zu, %zu, %zu, %zu normal values of sd 1 (se = 1 / sqrt(N), "
               "each look extending the last), the share %g spent over them by the Pocock-type Lan-DeMets function: "
               "look levels %.4g, %.4g, %.4g, %.4g (sum %.6g). Stated rates: a wrong verdict at most %g (the union "
               "bound); a right one at least the last look's power less the wrong verdicts that could stop the "
               "design first (powers %.5f to confirm at the margin, %.5f within at none, %.4f within at half). "
               "Mean N it took: none %.1f, half %.1f, margin %.1f, minus the margin %.1f. The boundary that ignores "
               "the number of looks (each look at the whole share %g) wrongly confirms at no effect at rate %.4f "
               "(reported, not gated; the rows reject from %u of %u: power 1 - %.2g against that rate; mutant "
               "claims-seq-looks-ignored).\n",
            SEQ_M, N[0], N[1], N[2], N[3], SEQ_ALPHA, aj[0], aj[1], aj[2], aj[3], asum, SEQ_ALPHA, pc_m, pt0, pt_half,
            nlook[T_NONE] / R, nlook[T_HALF] / R, nlook[T_MARGIN] / R, nlook[T_NEG] / R, SEQ_ALPHA, pn, kcs, R, pwn);
    sf_plot *pl = sf_result_plot(r, "verdict_rates", "Synthetic claims: each verdict's rate against the engine's",
                                 "row (1-5 at the boundary, 6 the 2-look design, 7 at the MDE, 8 at half, 9-17 sequential)",
                                 "rate [-]");
    sf_plot_log(pl, 0, 1);
    sf_plot_band(pl, "acceptance region (normal approx.)", NR, xs, lo, hi);
    sf_plot_series(pl, "stated rate", SF_STYLE_POINTS, NR, xs, p0);
    sf_plot_series(pl, "measured rate", SF_STYLE_POINTS, NR, xs, rate);
    for (int j = 0; j < NR; j++) {
        char q[SF_LABEL_LEN];
        double p;
        if (j >= S_NONE_CONF && seq_right(j)) {
            snprintf(q, sizeof q, "%s: not below its bound %.4f, one-sided exact binomial test (R = %u)", what[j], p0[j],
                     R);
            p = p_lower(k[j], p0[j], R);
        } else if (j >= S_NONE_CONF) {
            snprintf(q, sizeof q, "%s: not above the model share %.4g over the looks, one-sided exact binomial test "
                     "(R = %u)", what[j], p0[j], R);
            p = p_upper(k[j], p0[j], R);
        } else if (j == R_POWER) {
            snprintf(q, sizeof q, "%s: not below %.2f, one-sided exact binomial test (R = %u)", what[j], p0[j], R);
            p = p_lower(k[j], p0[j], R);
        } else if (j == R_HALF) {
            snprintf(q, sizeof q, "%s: at the exact power %.4f, two-sided exact binomial test (R = %u)", what[j],
                     p0[j], R);
            p = p_two(k[j], p0[j], R);
        } else {
            snprintf(q, sizeof q, "%s: not above %s %.4g, one-sided exact binomial test (R = %u)", what[j],
                     j == R_DESIGN ? "the claim's share" : "the test's alpha", p0[j], R);
            p = p_upper(k[j], p0[j], R);
        }
        sf_check_pvalue(r, q, p, level, R);
    }
    /* the exact rows: the engine's alpha a test is the synthetic case's
     * alpha / claims / looks, and a non-finite estimate is not decidable */
    sf_check_rel(r, "claims_alpha of the synthetic case (alpha 0.06, 3 claims, 2 looks)", a, p_test, 1e-15);
    sf_check_rel(r, "claims_mde at se = 1 and that alpha: (z_alpha + z_0.01) se", mde_engine, mde, 1e-12);
    /* the design's exact rows: its looks and levels */
    size_t Np[CLAIMS_MAX_LOOKS], Lp = claims_model_looks(100, 800, Np);
    int looks_ok = L == 4 && Lp == 4 && Np[0] == 100 && Np[1] == 200 && Np[2] == 400 && Np[3] == 800;
    looks_ok = looks_ok && claims_model_looks(100, 300, Np) == 3 && Np[2] == 300;
    sf_check_true(r, "the model looks: N = 100 to a budget 800 gives 100, 200, 400, 800; to 300, 100, 200, 300",
                  looks_ok, looks_ok ? "as stated" : "other looks");
    /* per-point budgets: nested doubling sequences, the largest the case's budget */
    const double pb_ok[3] = { 800, 3200, 3200 }, pb_odd[3] = { 800, 1000, 3200 }, pb_top[3] = { 800, 800, 1600 };
    int pb_fine = claims_budgets_ok(100, 3200, pb_ok, 3, 3) && claims_budgets_ok(100, 800, NULL, 0, 3) &&
                  !claims_budgets_ok(100, 3200, pb_odd, 3, 3) && !claims_budgets_ok(100, 3200, pb_top, 3, 3) &&
                  !claims_budgets_ok(100, 3200, pb_ok, 2, 3);
    size_t Na[CLAIMS_MAX_LOOKS], Nb[CLAIMS_MAX_LOOKS], La = claims_model_looks(100, 800, Na),
           Lb = claims_model_looks(100, 3200, Nb);
    for (size_t j = 0; j < La && j < Lb; j++)
        pb_fine = pb_fine && Na[j] == Nb[j];
    pb_fine = pb_fine && Lb == 6 && Nb[5] == 3200;
    sf_check_true(r, "per-point model budgets (model_budgets): 800, 3200, 3200 for 100 a look valid, 1000 (not 100 x "
                     "2^k), a largest below model_budget or a list of another length refused; the looks to 800 and "
                     "to 3200 agree where both look", pb_fine, pb_fine ? "as stated" : "other");
    sf_check_rel(r, "the look levels sum to the model share (the spending function at t = 1)", asum, SEQ_ALPHA, 1e-12);
    sf_check_rel(r, "the first look's level: alpha ln(1 + (e - 1) N_1 / N_L) (Lan & DeMets 1983, Pocock-type)", aj[0],
                 SEQ_ALPHA * log(1 + (exp(1.0) - 1) * (double)N[0] / (double)N[L - 1]), 1e-12);
    int nan_ok = claims_decide(up, NAN, 1, 4, a, NULL, NULL) == SF_CLAIM_UNDECIDED &&
                 claims_decide(up, 1, INFINITY, 4, a, NULL, NULL) == SF_CLAIM_UNDECIDED &&
                 claims_decide(eq, INFINITY, 1, 4, a, NULL, NULL) == SF_CLAIM_UNDECIDED;
    sf_check_true(r, "a NaN or infinite estimate or standard error is not decidable", nan_ok,
                  nan_ok ? "undecided" : "decided");
    return SF_SUCCESS;
}

const sf_check_def sf_checks_claims_synth[] = {
    { "claims_engine_synthetic", chk_claims_synth,
      "the claims engine's verdicts and alpha shares on synthetic claims of known truth (no solve)" },
    { NULL, NULL, NULL }
};
