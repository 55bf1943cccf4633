/* slipfield: Monte Carlo over realisations, reproducible by construction.
 *
 * Realisation i always gets the same random stream: an MT19937 seeded
 * with sf_mc_seed(seed, i), a SplitMix64 hash of the pair (counter-based,
 * so no stream depends on which thread or process ran the others).  Each
 * realisation writes its own slot of the output, so the result is
 * bit-identical for any thread count (OpenMP, dynamic schedule).
 *
 * Checkpointing: with a checkpoint path, every finished realisation is
 * appended as one line "i v1 v2 ..." (C99 hex floats: exact) and flushed;
 * a resumed run reads the file, keeps the complete lines whose header
 * matches this work (n, nout, key) and runs only the missing realisations.
 * A torn last line (killed mid-write) is ignored and redone.
 */
#ifndef SF_MONTECARLO_H
#define SF_MONTECARLO_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <gsl/gsl_rng.h>

typedef struct {
    size_t n;                 /* realisations 0 .. n-1 */
    size_t nout;              /* values per realisation */
    unsigned long seed;
    int threads;              /* 0: OpenMP's default */
    const char *checkpoint;   /* NULL: no checkpoint */
    int resume;               /* 1: reuse a matching checkpoint */
    unsigned long key;        /* identity of the work (e.g. a scene hash) */
    const char *label;        /* progress label (stderr, only on a TTY; see sf_mc_stage_lines) */
} sf_mc_spec;

typedef struct {
    /* per-thread workspace (plans are not shared between threads) */
    void *(*ws_alloc)(void *ctx);
    void (*ws_free)(void *ws);
    /* fill out[nout] for realisation i from rng; SF_SUCCESS or an error */
    int (*realise)(void *ws, size_t i, gsl_rng *rng, double *out);
} sf_mc_ops;

unsigned long sf_mc_seed(unsigned long seed, size_t i);

/* Set rng to realisation i's stream of seed: gsl_rng_set(rng,
 * sf_mc_seed(seed, i)), rng an MT19937 (gsl_rng_mt19937).  The one
 * seeding of realisation i: sf_mc_run seeds realisation i with it before
 * its realise call, and whatever re-runs one realisation of a sweep
 * (slipfield run --realisation, slipfield evaluate) seeds it with this. */
void sf_mc_stream(gsl_rng *rng, unsigned long seed, size_t i);

/* This process's MPI rank (0 without MPI) and *size (may be NULL).  In an
 * MPI build (make MPI=1, run under mpirun) sf_mc_run gives realisation i
 * to rank i mod size and gathers every value on every rank: the bytes are
 * those of the serial run. */
int sf_mc_rank(int *size);

/* on = 1: a labelled run whose stderr is not a terminal (no live count
 * there) prints on stderr one line with the time its first runs took and
 * an estimate of the rest (after a tenth of them or 30 s), and one when
 * they are done.  Process-wide, default 0 (the other commands' stderr
 * stays as it was); set it before the runs. */
void sf_mc_stage_lines(int on);

/* FNV-1a over bytes, chained through h (start with 0). */
unsigned long sf_mc_hash(const void *p, size_t n, unsigned long h);

/* Run every realisation not already in the checkpoint; out[n*nout].
 * *done_before (may be NULL) = realisations taken from the checkpoint.
 * Returns SF_SUCCESS, the first realisation error, SF_EIO (checkpoint) or
 * SF_EINVAL (a checkpoint for other work, with resume) with err set. */
int sf_mc_run(const sf_mc_spec *spec, const sf_mc_ops *ops, void *ctx, double *out,
              size_t *done_before, char *err, size_t errlen);

/* The same for realisations first .. upto-1 of the n of spec (upto is
 * clipped to n): those below first are taken as already in out (a
 * previous stage's, kept in the checkpoint, whose header still says n);
 * *done_before counts the range's realisations taken from the checkpoint.
 * Sample sizes decided in stages (mcstop.h) run through it. */
int sf_mc_run_range(const sf_mc_spec *spec, size_t first, size_t upto, const sf_mc_ops *ops, void *ctx,
                    double *out, size_t *done_before, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
