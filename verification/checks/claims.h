/* The claims engine's data model: a Monte Carlo sweep point (cpoint) with
 * its QoIs under each definition, and a claim of the paper (claim_spec)
 * judged on such points.  The paper's claims themselves (claims_paper.c)
 * are data on this header only; the engine (claims_engine.c) tests them. */
#ifndef SF_CHECKS_CLAIMS_H
#define SF_CHECKS_CLAIMS_H

#include <stddef.h>
#include "scene.h"
#include "sweep.h"

/* The QoI definitions each claim is judged under.  D_OURS is the paper's
 * (Sec. 3.1; the solver's qoi_def = paper, oscillator.h): T_sk = stick
 * time inside [t_skip, T] / (T - t_skip), PV_x and PV_F per oscillation
 * (a maximum of x to the next, stick or not), averaged within the
 * realisation.  The others are the sensitivity column:
 * D_TSKIP0, D_TSKIP_LATE: the paper's with t_skip = 0 and T/3;
 * D_CYCLES: complete stick-onset-to-onset cycles after t_skip (the
 *   solver's qoi_def = cycles; a realisation without one has no value);
 * D_SLIPCUT: cycles cut at slip onset, from the history;
 * D_POOLED: the spread over every oscillation of every realisation (the
 *   paper's "inside a single realisation and across realisations",
 *   Sec. 3.2): means as ours, std^2 = the variance of the per-realisation
 *   means + the mean within-realisation variance of the per-oscillation
 *   PVs (per-cycle stick fractions for T_sk; its tests use the
 *   realisation count as n);
 * D_PERCYCLE: "time duration of stick state" (Figs. 11-13 (c)) read as
 *   the stick duration per cycle: Q_SF is then the ratio of the per-cycle
 *   stick durations, Q_SFABS the stochastic duration itself [s]; the rest
 *   as ours;
 * D_EXCL_LO, D_EXCL_HI: selection sensitivity: ours with every realisation
 *   whose value could not be formed (NaN) counted at the smallest
 *   (largest) value of the others at that point. */
enum { D_OURS, D_TSKIP0, D_TSKIP_LATE, D_CYCLES, D_SLIPCUT, D_POOLED, ND_RAW, D_PERCYCLE = ND_RAW, D_EXCL_LO, D_EXCL_HI,
       ND };
/* QoIs per realisation and definition: ratios to the deterministic
 * reference for PVX, PVF, SF; SFABS = stochastic stick fraction itself;
 * TSTK = mean stick duration per complete cycle [s]; TSK = stick time
 * inside the window [s] (the paper's t_sk, Fig. 13(c)'s inset); BIFSD,
 * BIFMEAN = spread and mean of x at slip-to-stick within the realisation
 * [m]; BIFN = count; BIFREL = BIFSD / the deterministic PV_x [-];
 * SLIDE = the share of the window's oscillations without a stick phase. */
enum { Q_PVX, Q_PVF, Q_SF, Q_SFABS, Q_TSTK, Q_TSK, Q_BIFSD, Q_BIFMEAN, Q_BIFN, Q_BIFREL, Q_SLIDE, NQ };
/* after the ND_RAW x NQ block: the within-realisation variances of the
 * per-oscillation PV_x, PV_F and the per-cycle stick fraction, for
 * D_POOLED */
#define NW 3
#define NOUT (ND_RAW * NQ + NW)

typedef struct cpoint_s {
    double val;                 /* the parameter's value */
    size_t n;                   /* realisations */
    double *raw;                /* n x NOUT, then ratios in place for PVX, PVF, SF */
    double *raw0;               /* n x NOUT as the realisations wrote them (a model verdict's look extends it) */
    double recheck;             /* realisation 0 (and, extended, n-1) rerun alone: largest difference from its slot */
    double det[NOUT];           /* the deterministic reference, same definitions */
    double mean[ND][NQ], sd[ND][NQ];
    double ku[ND][NQ];          /* excess kurtosis of the per-realisation values (NAN below 4 values) */
    size_t nv[ND][NQ];          /* finite values */
    /* the paper's definitions' statistics (D_OURS) as `sweep --diagnostics`
     * states them (sf_sweep_stat_of: mean[D_OURS], sd[D_OURS], nv[D_OURS]
     * are its mean, std, n_used); the claims cases report them per point
     * and QoI */
    sf_sweep_stat stat[NQ];
    double *bif0, *bifdet;      /* slip-to-stick x of realisation 0 and of the deterministic run */
    size_t nbif0, nbifdet;
} cpoint;

/* ---- claim specs */
enum { K_MEAN, K_MEAN_EQ, K_DROP_EQ, K_SD, K_SD_EQ, K_HW100, K_CLUSTER, K_GAP };
/* A measured cause of a contradiction: computes, from this run, the
 * quantity the explanation names, writes it into buf (a sentence with the
 * measured numbers) and returns 1 when it holds (0: the explanation does
 * not apply to this run, and the claim's gate fails).  alpha is the
 * claim's own test level, for a cause that bounds a statistic. */
struct claim_spec_s;
typedef int (*claim_cause_fn)(const struct claim_spec_s *cs, const struct cpoint_s *pt, size_t K, const sf_scene *s,
                              double alpha, char *buf, size_t n);
typedef struct claim_spec_s {
    const char *id, *text;
    int kind, q;
    const char *a, *b;   /* point selectors: "=1" (that value), "<=0.1" (the first point, if at most 0.1),
                            ">=100" (the last point, if at least 100); b may be NULL */
    double lo, hi;       /* threshold (lo) or equivalence margin [lo, hi]; a directional claim's hi > 0 is
                            its model verdict's indifference margin (a factor for the std kinds; 0: the
                            default of claims_margin, claims_engine.c) */
    int dir;             /* +1: the claim says statistic > lo; -1: < lo */
    char decq, decp;     /* 'D': the quick / paper tier's N was chosen to decide this claim (not
                          * decidable fails the gate); '-': not demanded (see claim_gate) */
    const char *note;    /* the interpretation, or our explanation (no run's numbers: those are measured) */
    claim_cause_fn cause;   /* the measured cause behind a contradiction (NULL: none; a contradiction fails) */
} claim_spec;

/* The point a claim's selector ("=1", "<=0.1", ">=100") names among the K
 * sweep points, or -1 when the sweep has none (or sel is NULL). */
int claims_pick(const cpoint *pt, size_t K, const char *sel);

/* The paper's claims (claims_paper.c), each list ended by a NULL id. */
extern const claim_spec claims_lr[];     /* Figs. 10, 11, 16(a): the correlation length */
extern const claim_spec claims_vb[];     /* Figs. 12, 16(b): the belt speed */
extern const claim_spec claims_mu[];     /* Figs. 13, 16(c): the mean COF at fixed CV */
extern const claim_spec claims_fig15[];  /* Fig. 15: the spectra */
extern const claim_spec claims_fig3[];   /* Fig. 3: the fields */
extern const claim_spec claims_sobol[];  /* the abstract's "dominantly responsible": Sobol' indices */

#endif
