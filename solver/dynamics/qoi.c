/* slipfield: quantities of interest computed from a run's samples
 * (qoi.h): the periodogram. */
#include "qoi.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <complex.h>
#include <stdlib.h>
#include <fftw3.h>

int sf_periodogram(const double *x, size_t n, double dt, double *f, double *p)
{
    if (n < 2 || !(dt > 0))
        return SF_EINVAL;
    double *in = SF_FALLIBLE(fftw_malloc(n * sizeof *in));
    fftw_complex *out = SF_FALLIBLE(fftw_malloc((n / 2 + 1) * sizeof *out));
    if (!in || !out) {
        fftw_free(in);
        fftw_free(out);
        return SF_ENOMEM;
    }
    fftw_plan pl;
#pragma omp critical(sf_fftw_plan)
    pl = SF_FALLIBLE(fftw_plan_dft_r2c_1d((int)n, in, out, FFTW_ESTIMATE));
    if (!pl) {
        fftw_free(in);
        fftw_free(out);
        return SF_ENOMEM;
    }
    double mean = 0;
    for (size_t i = 0; i < n; i++)
        mean += x[i];
    mean /= (double)n;
    for (size_t i = 0; i < n; i++)
        in[i] = x[i] - mean;
    fftw_execute(pl);
    for (size_t k = 0; k <= n / 2; k++) {
        double c = (k == 0 || (n % 2 == 0 && k == n / 2)) ? 1 : 2;
        double a = cabs(out[k]);
        f[k] = (double)k / ((double)n * dt);
        p[k] = c * a * a * dt / (double)n;
    }
#pragma omp critical(sf_fftw_plan)
    fftw_destroy_plan(pl);
    fftw_free(in);
    fftw_free(out);
    return SF_SUCCESS;
}
