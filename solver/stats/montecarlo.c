/* slipfield: Monte Carlo over realisations, reproducible by construction
 * (montecarlo.h): the per-realisation streams, the OpenMP (and MPI) run
 * over them and its checkpoint. */
#include "montecarlo.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef SF_MPI
#include <mpi.h>
#endif

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

unsigned long sf_mc_seed(unsigned long seed, size_t i)
{
    return (unsigned long)splitmix64(splitmix64((uint64_t)seed) ^ (uint64_t)i);
}

void sf_mc_stream(gsl_rng *rng, unsigned long seed, size_t i)
{
    gsl_rng_set(rng, sf_mc_seed(seed, i));
}

unsigned long sf_mc_hash(const void *p, size_t n, unsigned long h)
{
    uint64_t x = h ? h : 0xcbf29ce484222325ULL;
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) {
        x ^= b[i];
        x *= 0x100000001b3ULL;
    }
    return (unsigned long)x;
}

/* Read the complete lines of a checkpoint into out/done. */
static int ck_read(const sf_mc_spec *s, double *out, unsigned char *done, char *err, size_t errlen)
{
    FILE *f = fopen(s->checkpoint, "r");
    if (!f)
        return SF_SUCCESS;   /* nothing to resume */
    char *line = NULL;
    size_t cap = 0;
    ssize_t len = getline(&line, &cap, f);
    unsigned long n, nout, key;
    if (len <= 0 || sscanf(line, "# slipfield checkpoint v1 n=%lu nout=%lu key=%lx", &n, &nout, &key) != 3) {
        free(line);
        fclose(f);
        return sf_seterr(err, errlen, SF_EINVAL, "%s: not a slipfield checkpoint", s->checkpoint);
    }
    if (n != s->n || nout != s->nout || key != s->key) {
        free(line);
        fclose(f);
        return sf_seterr(err, errlen, SF_EINVAL,
                         "%s: checkpoint of other work (scene, size or seed differ): remove it or drop --resume",
                         s->checkpoint);
    }
    double *v = sf_malloc((s->nout ? s->nout : 1) * sizeof *v);
    while (v && (len = getline(&line, &cap, f)) > 0) {
        if (line[len - 1] != '\n')
            break;               /* torn last line: redo it */
        char *p = line, *end;
        unsigned long i = strtoul(p, &end, 10);
        if (end == p || i >= s->n)
            continue;
        size_t k = 0;
        for (p = end; k < s->nout; k++, p = end) {
            v[k] = strtod(p, &end);
            if (end == p)
                break;
        }
        if (k < s->nout)
            continue;
        memcpy(out + i * s->nout, v, s->nout * sizeof *v);
        done[i] = 1;
    }
    free(v);
    free(line);
    fclose(f);
    return SF_SUCCESS;
}

int sf_mc_rank(int *size)
{
    int rank = 0, sz = 1;
#ifdef SF_MPI
    int init = 0;
    MPI_Initialized(&init);
    if (init) {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &sz);
    }
#endif
    if (size)
        *size = sz;
    return rank;
}

/* MPI: realisation i belongs to rank i mod size; the others are marked
 * done (they are not this rank's), computed elsewhere and gathered. */
static int gather(const sf_mc_spec *s0, size_t n, double *out, int rc)
{
#ifdef SF_MPI
    sf_mc_spec sn = *s0, *s = &sn;
    sn.n = n;   /* the realisations computed so far */
    int size, rank = sf_mc_rank(&size);
    if (size == 1)
        return rc;
    int all;
    MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (all)
        return all;
    size_t mine = 0;
    for (size_t i = (size_t)rank; i < s->n; i += (size_t)size)
        mine++;
    double *send = sf_malloc((mine ? mine : 1) * s->nout * sizeof *send);
    double *recv = sf_malloc((s->n ? s->n : 1) * s->nout * sizeof *recv);
    int *cnt = sf_malloc((size_t)size * sizeof *cnt), *dsp = sf_malloc((size_t)size * sizeof *dsp);
    if (!send || !recv || !cnt || !dsp) {
        free(send); free(recv); free(cnt); free(dsp);
        return SF_ENOMEM;
    }
    size_t k = 0;
    for (size_t i = (size_t)rank; i < s->n; i += (size_t)size, k++)
        memcpy(send + k * s->nout, out + i * s->nout, s->nout * sizeof *send);
    int off = 0;
    for (int q = 0; q < size; q++) {
        size_t m = s->n > (size_t)q ? (s->n - (size_t)q + (size_t)size - 1) / (size_t)size : 0;
        cnt[q] = (int)(m * s->nout);
        dsp[q] = off;
        off += cnt[q];
    }
    MPI_Allgatherv(send, cnt[rank], MPI_DOUBLE, recv, cnt, dsp, MPI_DOUBLE, MPI_COMM_WORLD);
    for (int q = 0; q < size; q++) {   /* unpack: rank q's k-th value is realisation q + k size */
        k = 0;
        for (size_t i = (size_t)q; i < s->n; i += (size_t)size, k++)
            memcpy(out + i * s->nout, recv + (size_t)dsp[q] + k * s->nout, s->nout * sizeof *out);
    }
    free(send); free(recv); free(cnt); free(dsp);
    return SF_SUCCESS;
#else
    (void)s0;
    (void)n;
    (void)out;
    return rc;
#endif
}

/* One checkpoint line: the realisation index and its outputs, exact (%a). */
static void ck_line(FILE *ck, size_t i, const double *v, size_t nout)
{
    fprintf(ck, "%zu", i);
    for (size_t k = 0; k < nout; k++)
        fprintf(ck, " %a", v[k]);
    fputc('\n', ck);
}

/* Start the checkpoint: read what a resumed run already has (done) and
 * rewrite exactly those lines, and those already in out (done too),
 * through a temporary file, so the file only ever holds complete lines of
 * this work; *ck is left open to append. */
static int ck_start(const sf_mc_spec *s, double *out, unsigned char *done, FILE **ck, char *err, size_t errlen)
{
    int rc;
    *ck = NULL;
    if (s->resume && (rc = ck_read(s, out, done, err, errlen)))
        return rc;
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp", s->checkpoint);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return sf_seterr(err, errlen, SF_EIO, "%s: cannot write the checkpoint", s->checkpoint);
    fprintf(f, "# slipfield checkpoint v1 n=%zu nout=%zu key=%lx\n", s->n, s->nout, s->key);
    for (size_t i = 0; i < s->n; i++)
        if (done[i])
            ck_line(f, i, out + i * s->nout, s->nout);
    if (fflush(f) || rename(tmp, s->checkpoint)) {
        fclose(f);
        return sf_seterr(err, errlen, SF_EIO, "%s: cannot write the checkpoint", s->checkpoint);
    }
    *ck = f;
    return SF_SUCCESS;
}

/* MPI: one checkpoint per rank (resume with the same rank count), progress
 * from rank 0 only.  ckpath holds the rank's checkpoint name. */
static void rank_spec(sf_mc_spec *s, int rank, int size, char *ckpath, size_t len)
{
    if (size > 1 && s->checkpoint) {
        snprintf(ckpath, len, "%s.rank%dof%d", s->checkpoint, rank, size);
        s->checkpoint = ckpath;
    }
    if (size > 1 && rank != 0)
        s->label = NULL;
}

static int stage_lines;

void sf_mc_stage_lines(int on)
{
    stage_lines = on;
}

/* The realisation loop's shared state. */
typedef struct {
    const sf_mc_spec *s;
    size_t first, upto;                   /* the realisations to run */
    double *out;
    const unsigned char *done, *theirs;   /* resumed; another rank's */
    FILE *ck;                             /* the checkpoint, open to append (or NULL) */
    size_t finished;
    int failed, rc, tty;
    size_t started;                       /* finished when the loop began (resumed) */
    double t0;                            /* its monotonic start time [s] */
    int lines, estimated;                 /* stage lines (off a terminal); the estimate printed */
} mc_loop;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Realisation i returned r: keep the first error, or checkpoint it and
 * report progress.  Called inside the critical section. */
static void record(mc_loop *L, size_t i, int r)
{
    const sf_mc_spec *s = L->s;
    if (r) {
        if (!L->failed)
            L->rc = r;
        L->failed = 1;
        return;
    }
    if (L->ck) {
        ck_line(L->ck, i, L->out + i * s->nout, s->nout);
        fflush(L->ck);
    }
    L->finished++;
    if (L->tty) {   /* ETA: this run's mean time per realisation so far */
        double dt = now_s() - L->t0, eta = dt / (double)(L->finished - L->started) * (double)(L->upto - L->finished);
        fprintf(stderr, "\r%s: %zu/%zu realisations, ETA %02d:%02d:%02d  ", s->label, L->finished, L->upto,
                (int)(eta / 3600), (int)fmod(eta / 60, 60), (int)fmod(eta, 60));
    } else if (L->lines && !L->estimated && L->finished < L->upto) {
        size_t k = L->finished - L->started, todo = L->upto - L->started;
        double dt = now_s() - L->t0;
        if ((10 * k >= todo) | (dt >= 30)) {
            L->estimated = 1;
            fprintf(stderr, "%s: the first %zu of %zu runs took %.2g s: about %.2g s more\n", s->label, k, todo, dt,
                    dt / (double)k * (double)(L->upto - L->finished));
        }
    }
}

/* The realisations not done yet, on an OpenMP team: each thread has its
 * own workspace and generator, realisation i its own stream (seed, i). */
static void realise_all(mc_loop *L, const sf_mc_ops *ops, void *ctx)
{
    const sf_mc_spec *s = L->s;
#ifdef _OPENMP
    int nt = s->threads > 0 ? s->threads : omp_get_max_threads();
#endif
#pragma omp parallel num_threads(nt)
    {
        void *ws = ops->ws_alloc ? ops->ws_alloc(ctx) : ctx;
        gsl_rng *rng = SF_FALLIBLE(gsl_rng_alloc(gsl_rng_mt19937));
        int ready = rng && (ws || !ops->ws_alloc);
        if (!ready) {
#pragma omp critical(sf_mc)
            {
                L->failed = 1;
                L->rc = SF_ENOMEM;
            }
        }
#pragma omp for schedule(dynamic, 1)
        for (size_t i = L->first; i < L->upto; i++) {
            int stop;
#pragma omp atomic read
            stop = L->failed;
            if (L->done[i] || L->theirs[i] || stop || !ready)
                continue;
            sf_mc_stream(rng, s->seed, i);
            int r = ops->realise(ws, i, rng, L->out + i * s->nout);
#pragma omp critical(sf_mc)
            record(L, i, r);
        }
        if (ops->ws_free && ws)
            ops->ws_free(ws);
        gsl_rng_free(rng);
    }
}

int sf_mc_run(const sf_mc_spec *spec, const sf_mc_ops *ops, void *ctx, double *out, size_t *done_before, char *err,
              size_t errlen)
{
    return sf_mc_run_range(spec, 0, spec->n, ops, ctx, out, done_before, err, errlen);
}

int sf_mc_run_range(const sf_mc_spec *s0, size_t first, size_t upto, const sf_mc_ops *ops, void *ctx, double *out,
                    size_t *done_before, char *err, size_t errlen)
{
    sf_mc_spec sl = *s0, *s = &sl;
    if (upto > s->n)
        upto = s->n;
    if (first > upto)
        first = upto;
    int size, rank = sf_mc_rank(&size);
    char ckpath[4200];
    rank_spec(s, rank, size, ckpath, sizeof ckpath);
    unsigned char *done = sf_calloc(s->n ? s->n : 1, 1);
    unsigned char *theirs = sf_calloc(s->n ? s->n : 1, 1);
    if (!done || !theirs) {
        free(done);
        free(theirs);
        return SF_ENOMEM;
    }
    for (size_t i = 0; i < s->n; i++) {
        theirs[i] = size > 1 && (int)(i % (size_t)size) != rank;
        done[i] = i < first;   /* already in out (gathered) */
    }
    FILE *ck = NULL;
    int rc = SF_SUCCESS;
    if (s->checkpoint && (rc = ck_start(s, out, done, &ck, err, errlen))) {
        free(done);
        free(theirs);
        return rc;
    }
    size_t before = 0;   /* of this range, from the checkpoint */
    for (size_t i = first; i < upto; i++)
        before += done[i];
    mc_loop L = { s, first, upto, out, done, theirs, ck, first + before, 0, SF_SUCCESS, s->label && isatty(2),
                  first + before, now_s(), 0, 0 };
    L.lines = s->label && stage_lines;   /* used off a terminal only (the tty arms come first) */
    realise_all(&L, ops, ctx);
    rc = L.rc;
    if (L.tty)
        fputc('\n', stderr);
    else if (L.lines && !rc)
        fprintf(stderr, "%s: %zu runs done in %.1f s\n", s->label, L.finished - L.started, now_s() - L.t0);
    if (ck && fclose(ck) && !rc) {
        rc = sf_seterr(err, errlen, SF_EIO, "%s: cannot write the checkpoint", s->checkpoint);
    }
    if (done_before)
        *done_before = before;
    free(done);
    free(theirs);
    return gather(s, upto, out, rc);
}
