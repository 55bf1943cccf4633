/* slipfield: quantities of interest computed from a run's samples.
 * (PV per oscillation and per cycle, the stick fraction T_sk, bifurcation
 * samples and the Eq. 15 error are accumulated by the integrator itself:
 * oscillator.h.) */
#ifndef SF_QOI_H
#define SF_QOI_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

/* One-sided periodogram of x[0..n-1] sampled every dt [s] (mean removed,
 * no window): f[k] = k / (n dt) [Hz], p[k] = c |X_k|^2 dt / n [m^2/Hz]
 * (c = 2 except at 0 and Nyquist), k = 0 .. n/2, by one FFTW r2c
 * transform.  f and p hold n/2 + 1 values.  Parseval: sum p df = var(x). */
int sf_periodogram(const double *x, size_t n, double dt, double *f, double *p);

#ifdef __cplusplus
}
#endif
#endif
