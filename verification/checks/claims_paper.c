/* The paper's claims (Hu, Batou & Ouyang 2023, Secs. 3-4) as data: what
 * each figure says, how we read it as a test on the sweep's points, and
 * the measured causes behind the contradictions we explain.  The engine
 * that tests them is claims_engine.c. */
#include "claims.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>

/* ---- Measured causes (claim_cause_fn): each computes, from this run,
 * the quantity a contradiction's explanation names. */

/* A point's mean ratio of quantity q under ours, its standard error. */
static double pt_mean(const cpoint *p, int q, double *se)
{
    *se = p->sd[D_OURS][q] / sqrt((double)p->nv[D_OURS][q]);
    return p->mean[D_OURS][q];
}

/* One COF value per realisation: the 1-D cycle's amplitude A = sqrt(d^2 +
 * (v_r/omega)^2) passes a relative fluctuation of d (proportional to
 * mu_s) with the weight d^2 / A^2, so the std of the PV_x ratio is about
 * that weight times the COF's CV; d = PV_F / (2 k) and A = PV_x / 2 from
 * the deterministic run.  Holds when the predicted std is below the
 * claim's margin. */
static int cause_pvx_weight(const claim_spec *cs, const cpoint *pt, size_t K, const sf_scene *s, double alpha,
                           char *buf, size_t n)
{
    (void)alpha;
    int a = claims_pick(pt, K, cs->a);
    const double *d = pt[a].det + D_OURS * NQ;
    double dd = d[Q_PVF] / (2 * s->k), A = d[Q_PVX] / 2, w = dd * dd / (A * A), cv = s->mu_std / s->mu_mean;
    snprintf(buf, n, "the deterministic run's amplitude law passes the COF's CV = %.3g with the weight d^2/A^2 = %.3f "
             "(d = PV_F/2k = %.4g m, A = PV_x/2 = %.4g m): predicted std %.3f, against the margin's %.3g; measured "
             "%.3f.", cv, w, dd, A, w * cv, cs->lo, pt[a].sd[D_OURS][cs->q]);
    return w * cv < cs->lo;
}

/* Longer stick phases: the PV ratio's excess at the point comes with stick
 * phases per cycle longer than the deterministic ones (PV_F = k x the
 * stick travel v_b t_stick in the 1-D cycle; PV_x grows with d).  Holds
 * when the stick-per-cycle ratio is above one beyond 2 standard errors. */
static int cause_longer_stick(const claim_spec *cs, const cpoint *pt, size_t K, const sf_scene *s, double alpha,
                           char *buf, size_t n)
{
    (void)alpha;
    (void)s;
    int a = claims_pick(pt, K, cs->a);
    const cpoint *p = &pt[a];
    double det = p->det[D_OURS * NQ + Q_TSTK], se, m = pt_mean(p, Q_TSTK, &se);
    snprintf(buf, n, "at %g the stick phases per cycle last %.3f +- %.3f s against %.3f s deterministic (ratio %.3f): "
             "a stick threshold from the upper tail of the field holds the disc longer, and the stick travel sets "
             "PV_F (k v_b t_stick) and d in PV_x.", p->val, m, se, det, m / det);
    return m - 2 * se > det;
}

/* The deterministic stick fraction itself falls: the claim's drop read on
 * the stochastic T_sk is then the deterministic model's.  Holds when the
 * deterministic T_sk falls by more than the margin's upper end. */
static int cause_det_sf_falls(const claim_spec *cs, const cpoint *pt, size_t K, const sf_scene *s, double alpha,
                           char *buf, size_t n)
{
    (void)alpha;
    (void)s;
    int a = claims_pick(pt, K, cs->a), b = claims_pick(pt, K, cs->b);
    double da = pt[a].det[D_OURS * NQ + Q_SF], db = pt[b].det[D_OURS * NQ + Q_SF];
    snprintf(buf, n, "the deterministic T_sk itself falls by %.1f%% (%.4f at %g, %.4f at %g): t_stick = 2 d / v_b "
             "shrinks while the slip lengthens.", 100 * (1 - da / db), db, pt[b].val, da, pt[a].val);
    return 1 - da / db > cs->hi;
}

/* Oscillations that slide on: the share without a stick phase at both
 * points (what the per-cycle definitions left out).  Holds when the
 * shares differ by more than a tenth of the oscillations: the mixture of
 * sliding and sticking oscillations, not the stick cycles alone, moves
 * the statistic. */
static int cause_slide_share(const claim_spec *cs, const cpoint *pt, size_t K, const sf_scene *s, double alpha,
                           char *buf, size_t n)
{
    (void)alpha;
    (void)s;
    int a = claims_pick(pt, K, cs->a), b = claims_pick(pt, K, cs->b);
    double sa = pt[a].mean[D_OURS][Q_SLIDE], sb = pt[b].mean[D_OURS][Q_SLIDE];
    snprintf(buf, n, "%.0f%% of the oscillations in the window have no stick phase at %g, %.0f%% at %g.", 100 * sa,
             pt[a].val, 100 * sb, pt[b].val);
    return fabs(sa - sb) > 0.1;
}

/* The paper's Monte Carlo resolution of a mean: its 95% half-width at N =
 * 100 realisations, with the per-realisation spread sd measured over this
 * run's window scaled to the paper's, [10, 100] s (the spread of a window
 * mean goes as 1 / sqrt(T - t_skip)). */
static double paper_halfwidth(double sd, const sf_scene *s)
{
    return 1.96 * sd / 10 * sqrt((s->T - s->t_skip) / (100.0 - 10.0));
}

/* A short window: the per-realisation mean averages the oscillations of
 * [t_skip, T] only, so its spread (and the half-width at N = 100) scales
 * as 1 / sqrt(T - t_skip).  Holds when, scaled to the paper's window (T =
 * 100 s, t_skip = 10 s), the measured half-width would be below the
 * claim's threshold. */
static int cause_short_window(const claim_spec *cs, const cpoint *pt, size_t K, const sf_scene *s, double alpha,
                           char *buf, size_t n)
{
    (void)alpha;
    int a = claims_pick(pt, K, cs->a);
    double hw = 1.96 * pt[a].sd[D_OURS][cs->q] / 10 / pt[a].mean[D_OURS][cs->q];
    double scaled = paper_halfwidth(pt[a].sd[D_OURS][cs->q], s) / pt[a].mean[D_OURS][cs->q];
    snprintf(buf, n, "the window [%g, %g] s holds %.1f slip-to-stick events per realisation; the relative half-width "
             "%.3f scaled to the paper's window [10, 100] s is %.3f, against %.3g.", s->t_skip, s->T,
             pt[a].mean[D_OURS][Q_BIFN], hw, scaled, cs->lo);
    return scaled < cs->lo;
}

/* Below the paper's resolution: a mean that departs from the claim's
 * threshold by less than the paper's own Fig. 11 could show (its 95%
 * half-width at N = 100 over its window, paper_halfwidth).  Holds when the
 * departure's one-sided (1 - alpha) lower bound, at the claim's alpha, is
 * below that half-width: the contradiction is real at this N but smaller
 * than anything the figure resolves, so it says nothing about the
 * figure's reading.  A departure clearly larger (a defect moving the
 * ratio by several standard errors more) fails. */
static int cause_below_resolution(const claim_spec *cs, const cpoint *pt, size_t K, const sf_scene *s, double alpha,
                                  char *buf, size_t n)
{
    int a = claims_pick(pt, K, cs->a);
    const cpoint *p = &pt[a];
    double se, m = pt_mean(p, cs->q, &se), nv = (double)p->nv[D_OURS][cs->q];
    double dev = fabs(m - cs->lo), lb = dev - gsl_cdf_tdist_Qinv(alpha, nv - 1) * se;
    double hw = paper_halfwidth(p->sd[D_OURS][cs->q], s);
    snprintf(buf, n, "at %g the mean %.4f departs from %g by %.4f, at least %.4f (one-sided, alpha %.2g); the paper's "
             "resolution at N = 100 over [10, 100] s is +-%.4f (95%%).", p->val, m, cs->lo, dev, lb, alpha, hw);
    return lb < hw;
}

/* ---- Figs. 10, 11, 16(a): the correlation length */
const claim_spec claims_lr[] = {
    { "fig10-converged", "The mean of Delta x_s / Delta x_d converges once the number of realisations exceeds 100 "
      "(Fig. 10); read: its 95% half-width at N = 100 is below 5% of the mean", K_HW100, Q_PVX, "=1", NULL, 0.05, 0, -1,
      '-', 'D', "At l/R = 1, where the spread is largest. The half-width scales with the std of the per-realisation "
      "means, which shrinks with the oscillations a realisation holds: a short window (the quick tier's T = 20 s) "
      "leaves it undecided or contradicted.", cause_short_window },
    { "fig11-small-mean-x", "l/R < 0.1: the mean PV_x ratio approaches 1 (the model degenerates to the deterministic one)",
      K_MEAN_EQ, Q_PVX, "<=0.1", NULL, 0.95, 1.05, 0, '-', 'D',
      "Judged at the grid's smallest l/R (0.01 at the paper tier). PV_x homogenises slowest: it depends on mu_s - mu_k, "
      "10% of mu, and the amplitude is convex in it.", NULL },
    { "fig11-small-mean-F", "l/R < 0.1: the mean PV_F ratio approaches 1", K_MEAN_EQ, Q_PVF, "<=0.1", NULL, 0.95, 1.05, 0,
      '-', 'D', NULL, NULL },
    { "fig11-small-mean-sf", "l/R < 0.1: the mean stick-duration ratio approaches 1", K_MEAN_EQ, Q_SF, "<=0.1", NULL, 0.95,
      1.05, 0, '-', 'D', NULL, NULL },
    { "fig11-small-std-x", "l/R < 0.1: the std of the PV_x ratio vanishes (read: below 0.05)", K_SD, Q_PVX, "<=0.1", NULL,
      0.05, 0, -1, '-', 'D', "The spread of the per-realisation means.", NULL },
    { "fig11-small-std-F", "l/R < 0.1: the std of the PV_F ratio vanishes (read: below 0.05)", K_SD, Q_PVF, "<=0.1", NULL,
      0.05, 0, -1, '-', 'D', NULL, NULL },
    { "fig11c-small-std-sf", "Fig. 11(c): l/R < 0.1: the std of the stick-duration ratio vanishes (read: below 0.05)",
      K_SD, Q_SF, "<=0.1", NULL, 0.05, 0, -1, '-', '-', NULL, NULL },
    { "fig11-peak-x", "The std of the PV_x ratio is largest near l/R = 1: larger than at the smallest l/R (0.01; quick tier: 0.25)", K_SD, Q_PVX,
      "=1", "<=0.25", 1, 0, +1, 'D', 'D', NULL, NULL },
    { "fig11-peak-x-large", "The std of the PV_x ratio is largest near l/R = 1: larger than at l/R > 100", K_SD, Q_PVX,
      "=1", ">=100", 1, 0, +1, '-', '-',
      "The per-realisation mean over its oscillations averages the oscillation-to-oscillation scatter at l/R = 1; at "
      "large l/R (one COF per realisation) there is none to average. The paper pools oscillations across "
      "realisations (its ergodicity remark, Sec. 3.2): see 'pooled' in the sensitivity column.", NULL },
    { "fig11-peak-F", "The std of the PV_F ratio is largest near l/R = 1: larger than at the smallest l/R (0.01; quick tier: 0.25)", K_SD, Q_PVF,
      "=1", "<=0.25", 1, 0, +1, 'D', 'D', NULL, NULL },
    { "fig11-peak-F-large", "The std of the PV_F ratio is largest near l/R = 1: larger than at l/R > 100", K_SD, Q_PVF,
      "=1", ">=100", 1, 0, +1, '-', '-', "As fig11-peak-x-large.", NULL },
    { "fig11-mid-mean-x", "l/R of order 1: the mean PV_x ratio fluctuates around one (read: within 1 +- 0.1)", K_MEAN_EQ,
      Q_PVX, "=1", NULL, 0.9, 1.1, 0, '-', '-',
      "PV_x is convex in mu_s - mu_k and grows with the stick travel; the paper's curve may be a single realisation "
      "per point.", cause_longer_stick },
    { "fig11-mid-mean-F", "l/R of order 1: the mean PV_F ratio fluctuates around one (read: within 1 +- 0.1)", K_MEAN_EQ,
      Q_PVF, "=1", NULL, 0.9, 1.1, 0, '-', '-', "PV_F includes the static peak of each oscillation, the largest stick "
      "threshold the disc meets.", cause_longer_stick },
    { "fig11-large-std-x", "l/R > 100: the std of the PV_x ratio tends to CV = 0.2 (read: within 0.2 +- 20%)", K_SD_EQ,
      Q_PVX, ">=100", NULL, 0.16, 0.24, 0, 'D', '-',
      "Exact in the one-variable limit: only PV_F, linear in mu_s, has std CV; the quadrature of quick-mean-cof's "
      "oracle gives 0.135 for PV_x over the lognormal mu_s.", cause_pvx_weight },
    { "fig11-large-std-F", "l/R > 100: the std of the PV_F ratio tends to CV = 0.2 (read: within 0.2 +- 20%)", K_SD_EQ,
      Q_PVF, ">=100", NULL, 0.16, 0.24, 0, 'D', '-',
      "Exact behind it: PV_F = 2 (1 - mu_k/mu_s) mu_s m g with one mu_s per realisation, so the ratio is mu_s/mean "
      "(the chi-square test of its log's variance below).", NULL },
    { "fig11-large-std-sf", "l/R > 100: the std of the stick-duration ratio tends to CV = 0.2 (read: within 0.2 +- 20%)",
      K_SD_EQ, Q_SF, ">=100", NULL, 0.16, 0.24, 0, '-', '-',
      "Under the paper's T_sk the window holds the long first stick from rest (x_s / v_b, proportional to mu_s) as "
      "well as the cycles' (2 d / v_b, proportional to mu_s), so the ratio follows mu_s more closely than the "
      "cycle's stick fraction t_stick / (t_stick + t_slip), whose slip lasts at least pi/omega whatever mu_s "
      "(std 0.143 over the lognormal mu_s: see 'cycles').", NULL },
    { "fig11-large-mean-x", "l/R > 100: the mean PV_x ratio is slightly lower than one", K_MEAN, Q_PVX, ">=100", NULL, 1, 0,
      -1, '-', '-', "With one mu_s per realisation the 1-D cycle's amplitude is convex in mu_s: its mean is above 1.",
      NULL },
    { "fig11-large-mean-F", "l/R > 100: the mean PV_F ratio is slightly lower than one", K_MEAN, Q_PVF, ">=100", NULL, 1, 0,
      -1, '-', '-', "Exact: the PV_F ratio is mu_s / mean, whose mean is 1; no N can confirm 'lower than one'.", NULL },
    { "fig11-stable-mean-x", "Fig. 11: for l/R > 100 the mean stabilises (read: the mean PV_x ratio at l/R = 1000 within "
      "+-0.05 of that at 100)", K_MEAN_EQ, Q_PVX, "=1000", "=100", -0.05, 0.05, 0, '-', '-', NULL, NULL },
    { "fig11-stable-mean-F", "... the mean PV_F ratio at l/R = 1000 within +-0.05 of that at 100", K_MEAN_EQ, Q_PVF,
      "=1000", "=100", -0.05, 0.05, 0, '-', '-', NULL, NULL },
    { "fig11-stable-mean-sf", "... the mean stick-duration ratio at l/R = 1000 within +-0.05 of that at 100", K_MEAN_EQ,
      Q_SF, "=1000", "=100", -0.05, 0.05, 0, '-', '-', NULL, NULL },
    { "fig11-stable-std-x", "Fig. 11: for l/R > 100 the standard deviation stabilises (read: the std of the PV_x ratio at "
      "l/R = 1000 within a factor 1.25 of that at 100)", K_SD_EQ, Q_PVX, "=1000", "=100", 0.8, 1.25, 0, '-', '-', NULL,
      NULL },
    { "fig11-stable-std-F", "... the std of the PV_F ratio at 1000 within a factor 1.25 of that at 100", K_SD_EQ, Q_PVF,
      "=1000", "=100", 0.8, 1.25, 0, '-', '-', NULL, NULL },
    { "fig11-stable-std-sf", "... the std of the stick-duration ratio at 1000 within a factor 1.25 of that at 100",
      K_SD_EQ, Q_SF, "=1000", "=100", 0.8, 1.25, 0, '-', '-', NULL, NULL },
    { "fig11-mid-sf-bends", "l/R between 0.1 and 10: the mean stick-duration ratio bends downward from one (at l/R = 1)",
      K_MEAN, Q_SF, "=1", NULL, 1, 0, -1, '-', '-', "A bend of a few percent at most, at the edge of N = 100 (a departure past one that the paper's figure "
      "could not resolve is the measured cause of a contradiction): "
      "not decidable under the per-cycle stick fraction ('cycles'), which leaves out the window's partial stick "
      "spans and the realisations' longest sticks at its ends; T_sk counts them.", cause_below_resolution },
    { "fig11-mid-sf-std", "The stick duration fluctuates the most for l/R between 0.1 and 10 (std at l/R = 1 above l/R > 100)",
      K_SD, Q_SF, "=1", ">=100", 1, 0, +1, '-', '-', NULL, NULL },
    { "fig16a-small-steady", "Fig. 16(a): for l/R < 0.1 the system has one steady state like the deterministic one "
      "(read: the spread of x at slip-to-stick at the smallest l/R, 0.01 (quick tier: 0.25), is smaller than at l/R = 1)", K_MEAN, Q_BIFSD, "=1", "<=0.25", 0, 0, +1,
      'D', 'D', NULL, NULL },
    { "fig16a-mid-no-steady-1", "Fig. 16(a): for l/R between 1 and 10 the results are significantly dispersed, no "
      "steady state exists; read: at l/R = 1 the spread of x at slip-to-stick within a realisation exceeds 5% of the "
      "deterministic PV_x (a steady state has none)", K_MEAN, Q_BIFREL, "=1", NULL, 0.05, 0, +1, '-', '-', NULL, NULL },
    { "fig16a-mid-no-steady-10", "... the same at l/R = 10", K_MEAN, Q_BIFREL, "=10", NULL, 0.05, 0, +1, '-', '-', NULL,
      NULL },
    { "fig16a-large-clusters", "Fig. 16(a): for l/R > 100 multiple steady states (separable clusters); read: each "
      "realisation settles on its own state, x at slip-to-stick varies more between realisations than within one",
      K_CLUSTER, Q_BIFSD, ">=100", NULL, 1, 0, +1, 'D', 'D',
      "Interpretation: with l >> the strip, one realisation has (nearly) one COF and one limit cycle; different "
      "realisations have different cycles, so a diagram over several realisations shows clusters.", NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};

/* ---- Figs. 12, 16(b): the belt speed */
const claim_spec claims_vb[] = {
    { "fig12-mean-x-falls", "All QoI are negatively impacted in the mean sense as v_b grows: PV_x ratio at 0.6 below 0.1",
      K_MEAN, Q_PVX, ">=0.6", "<=0.1", 0, 0, -1, '-', '-', NULL, NULL },
    { "fig12-mean-F-falls", "... PV_F ratio at v_b = 0.6 below 0.1", K_MEAN, Q_PVF, ">=0.6", "<=0.1", 0, 0, -1, '-', 'D',
      "Under the paper's PV (every oscillation, stick or not) the oscillations that slide on at a fast belt count, "
      "with the small force range of a slip; the old per-cycle PV kept only the stick cycles, whose range widens "
      "with v_b (see 'cycles').", cause_slide_share },
    { "fig12-mean-sf-falls", "... stick-duration ratio at v_b = 0.6 below 0.1: the stochasticity exacerbates the fall "
      "of the stick duration (also conclusion 2)", K_MEAN, Q_SF, ">=0.6", "<=0.1", 0, 0, -1, '-', 'D', NULL, NULL },
    { "fig12-drop-x", "The mean PV_x drops by around 20% over v_b = 0.1 .. 0.6 (read: a drop of the mean ratio in "
      "[10%, 30%])", K_DROP_EQ, Q_PVX, ">=0.6", "<=0.1", 0.1, 0.3, 0, '-', '-',
      "Contradicted under the old per-cycle PV (a drop of a few percent: at a fast belt the field-free v_b/omega "
      "term dominates a stick cycle's amplitude). The paper's PV also counts the oscillations that slide on without "
      "a stick phase, whose amplitude about the sliding equilibrium is smaller than a stick cycle's.",
      cause_slide_share },
    { "fig12-drop-F", "The mean PV_F drops by around 20% over v_b = 0.1 .. 0.6 (read: in [10%, 30%])", K_DROP_EQ, Q_PVF,
      ">=0.6", "<=0.1", 0.1, 0.3, 0, '-', '-',
      "Contradicted under the old per-cycle PV (it rose: a stick cycle's force range spans the stick threshold); an "
      "oscillation that slides on without a stick phase has only the kinetic force's variation along the belt.",
      cause_slide_share },
    { "fig12-drop-sf", "The mean stick duration drops by around 40% at v_b = 0.6 against 0.1 (read: the ratio to the "
      "deterministic model, a drop in [30%, 50%])", K_DROP_EQ, Q_SF, ">=0.6", "<=0.1", 0.3, 0.5, 0, '-', '-',
      "Contradicted under the old per-cycle stick fraction, which dropped the realisations that slide on at a fast "
      "belt (those that stick least) and divided by the complete cycles' time only (see 'cycles').", cause_slide_share },
    { "fig12-drop-sf-abs", "The same 40% drop read on the stochastic stick fraction itself (in [30%, 50%])", K_DROP_EQ,
      Q_SFABS, ">=0.6", "<=0.1", 0.3, 0.5, 0, 'D', 'D',
      "Read on the stick fraction itself the fall is set by the deterministic model, not 40%.", cause_det_sf_falls },
    { "fig12-std-x-grows", "The variation of PV_x increases (slightly) with v_b: std at 0.6 above 0.1", K_SD, Q_PVX, ">=0.6",
      "<=0.1", 1, 0, +1, '-', '-', NULL, NULL },
    { "fig12-std-F-massive", "The variation of the friction force expands massively with v_b (read: std of the PV_F ratio "
      "at 0.6 more than twice that at 0.1)", K_SD, Q_PVF, ">=0.6", "<=0.1", 2, 0, +1, '-', '-', NULL, NULL },
    { "fig16b-flat", "Fig. 16(b): the belt speed is not prominent upon the bifurcation behaviour; the slip-to-stick "
      "positions scatter at about the same level (read: spread at 0.6 within a factor 2 of that at 0.1)", K_SD_EQ,
      Q_BIFSD, ">=0.6", "<=0.1", 0.5, 2, 0, '-', '-', "Tested on the spread's spread across realisations: the ratio of "
      "the std of the per-realisation spread; see the table for the spreads themselves.", NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};

/* ---- Figs. 13, 16(c): the mean COF at fixed CV */
const claim_spec claims_mu[] = {
    { "fig13-mean-x-rises", "Increasing mu impacts positively all QoI: the mean PV_x ratio at mu = 1 above mu = 0.2",
      K_MEAN, Q_PVX, ">=1", "<=0.2", 0, 0, +1, '-', '-', NULL, NULL },
    { "fig13-mean-F-rises", "... the mean PV_F ratio at mu = 1 above mu = 0.2", K_MEAN, Q_PVF, ">=1", "<=0.2", 0, 0, +1,
      '-', '-', NULL, NULL },
    { "fig13-mean-sf-rises", "... the mean stick-duration ratio at mu = 1 above mu = 0.2", K_MEAN, Q_SF, ">=1", "<=0.2", 0,
      0, +1, '-', '-', NULL, NULL },
    { "fig13-sat-x", "The mean ratios saturate at one (PV_x ratio at mu = 1 within 1 +- 0.05)", K_MEAN_EQ, Q_PVX, ">=1",
      NULL, 0.95, 1.05, 0, '-', '-',
      "At fixed CV every friction length scales with mu except v_b/omega and the correlation length: at mu = 1 a "
      "stick carries the patch 2 d = 0.65 m = 6.5 l (0.13 m at 0.2), so an oscillation meets more independent COF "
      "values; and PV_x follows d at mu = 1 (weight d^2 / (d^2 + (v_r/omega)^2): 0.24 at 0.2, 0.89 at 1, Table 1). "
      "In the one-variable limit the exact mean ratio at mu = 1 is 1.002 (quick-mean-cof): an excess is the field's.",
      cause_longer_stick },
    { "fig13-sat-F", "... PV_F ratio at mu = 1 within 1 +- 0.05", K_MEAN_EQ, Q_PVF, ">=1", NULL, 0.95, 1.05, 0, '-', '-',
      "As fig13-sat-x: PV_F spans the stick travel, over more COF values as mu grows; in the one-variable limit its "
      "exact mean ratio is 1 at every mu (quick-mean-cof).", cause_longer_stick },
    { "fig13-sat-sf", "... stick-duration ratio at mu = 1 within 1 +- 0.05", K_MEAN_EQ, Q_SF, ">=1", NULL, 0.95, 1.05, 0,
      '-', '-', NULL, NULL },
    { "fig13-std-x-stable", "The variation of PV_x remains stable over mu (std at 1 within a factor 1.5 of that at 0.2)",
      K_SD_EQ, Q_PVX, ">=1", "<=0.2", 1 / 1.5, 1.5, 0, '-', '-',
      "Under the paper's PV the spread falls with mu: at mu = 0.2 a large share of the oscillations slide on without "
      "a stick phase, and a realisation's mean PV mixes them with stick cycles; at mu = 1 nearly all stick. Under "
      "the per-cycle PV ('cycles') the spread grows instead, as the closed form's weight d^2 / (d^2 + "
      "(v_r/omega)^2) predicts (0.24 at mu = 0.2, 0.89 at 1, Table 1).", cause_slide_share },
    { "fig13-std-F-grows", "The variation of the friction force increases significantly after mu > 0.8 (std of the PV_F "
      "ratio at 1 above 0.8)", K_SD, Q_PVF, ">=1", "=0.8", 1, 0, +1, '-', '-', NULL, NULL },
    { "fig13-std-sf-shrinks", "The variation of the stick duration shrinks as mu grows (std at 1 below 0.2; conclusion 3)",
      K_SD, Q_SF, ">=1", "<=0.2", 1, 0, -1, '-', 'D', NULL, NULL },
    { "fig13-stick-longer", "Fig. 13(c), inset: the stick duration (with dimensions, t_sk) becomes longer with mu (at 1 "
      "above 0.2)", K_MEAN, Q_TSK, ">=1", "<=0.2", 0, 0, +1, 'D', 'D', NULL, NULL },
    { "fig13c-inset-approach", "Fig. 13(c), inset: the stochastic stick duration approaches the deterministic one as mu "
      "grows (read: |mean t_sk,s / t_sk,d - 1| at mu = 1 below that at 0.2)", K_GAP, Q_SF, ">=1", "<=0.2", 0, 0, -1,
      '-', '-', "Same window for both models, so the ratio of the stick times is the T_sk ratio.", NULL },
    { "fig16c-dispersion", "Fig. 16(c): the mean COF increases the dispersion of x at slip-to-stick (spread at 1 above 0.2)",
      K_MEAN, Q_BIFSD, ">=1", "<=0.2", 0, 0, +1, '-', 'D', "Partly dimensional: x scales with mu m g / k.", NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};

/* ---- Fig. 15: the spectra (judged from the harmonic shares, chk_claims_fig15) */
const claim_spec claims_fig15[] = {
    { "fig15-noise-peaks-at-1", "Fig. 15: the noise level is higher at l/R = 1 than at l/R = 0.1 (no meaningful pattern "
      "at 1); read: less of the power at the deterministic harmonics", K_MEAN, 0, NULL, NULL, 0, 0, -1, 'D', 'D', NULL,
      NULL },
    { "fig15-noise-reduced-at-10", "Fig. 15: at l/R = 10 the noise level is substantially reduced against l/R = 1; read: "
      "more of the power at the deterministic harmonics", K_MEAN, 0, NULL, NULL, 0, 0, +1, '-', '-',
      "Depends on the window (the table gives the shares): in 100 s the belt brings 20 m of field, four "
      "correlation lengths at l/R = 10, under the disc, so the cycle drifts and its harmonics smear.", NULL },
    { "fig15-noisy-at-0.1", "Fig. 15: at l/R = 0.1 the spectrum follows the deterministic peaks but with significant "
      "noise; read: less power at the harmonics than the deterministic response", K_MEAN, 0, NULL, NULL, 0, 0, -1, '-',
      'D', NULL, NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};

/* ---- Fig. 3: the fields themselves (chk_fig3) */
const claim_spec claims_fig3[] = {
    { "fig3-length-scale", "Fig. 3 / Sec. 3.2: the correlation length determines how the randomness is distributed in "
      "space; read: the mean square COF increment over 0.05 m falls from l/R = 0.1 to l/R = 10", K_MEAN, 0, NULL, NULL,
      0, 0, -1, 'D', 'D', NULL, NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};

/* ---- The abstract: the correlation length "dominantly responsible",
 * judged by the Sobol' study (checks/sensitivity.c), not on sweep points:
 * per QoI ratio, the smallest gap between the total index of log10 l/R
 * and that of CV, v_b or the mean COF; lo = 0, dir = +1: the claim says
 * the gap is positive. */
const claim_spec claims_sobol[] = {
    { "sobol-lr-dominant-x", "Abstract: the correlation length is dominantly responsible for the stochastic "
      "behaviours; read: in the PV_x ratio, log10 l/R's first-order Sobol' index exceeds that of the CV, v_b and the "
      "mean COF, and so does its total index (the field a white noise fixed on the belt)",
      K_MEAN, Q_PVX, NULL, NULL, 0, 0, +1, '-', '-',
      "Over the paper's ranges (log10 l/R in [-2, 3], v_b in [0.1, 0.6] m/s, mean COF in [0.2, 1]) and CV in [0.1, "
      "0.3]; the field itself is a fifth input.", NULL },
    { "sobol-lr-dominant-F", "Abstract, as sobol-lr-dominant-x, for the PV_F ratio", K_MEAN, Q_PVF, NULL, NULL, 0, 0,
      +1, '-', '-', NULL, NULL },
    { "sobol-lr-dominant-sf", "Abstract, as sobol-lr-dominant-x, for the stick-duration ratio (the abstract adds that "
      "v_b and the mean COF have a significant influence on it)", K_MEAN, Q_SF, NULL, NULL, 0, 0, +1, '-', '-', NULL,
      NULL },
    { NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, 0, NULL, NULL }
};
