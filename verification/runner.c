/* slipfield verify: run cases, each in its own process (a crash, abort or
 * time-out in one is that case's failure and the rest still run), write
 * the reports and gate on the verdicts. */
#include "runner.h"
#include "budget.h"
#include "case.h"
#include "casetime.h"
#include "drift.h"
#include "registry.h"
#include "paper.h"
#include "report.h"
#include "result.h"
#include "results.h"
#include "montecarlo.h"
#include "options.h"
#include "sf_error.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void usage(FILE *f)
{
    fputs("usage: slipfield verify [options] CASE.md...\n"
          "Run literate verification cases, write reports, exit 0 only if all pass.\n\n"
          "options:\n"
          "  --tier quick|full|paper  quick (default) runs tier=quick cases; full runs\n"
          "                      quick and full; paper runs only tier=paper cases (the\n"
          "                      paper's settings, reports/paper.md)\n"
          "  --reports DIR       report folder (default: reports)\n"
          "  --jobs N            cases run in parallel (default 1)\n"
          "  --timeout S         per-case wall-time limit in seconds (default 900); without it each\n"
          "                      case also gets a CPU-time limit of 20x its recorded CPU time\n"
          "                      (cases/times.tsv), at least 60 s, and a wall limit no shorter\n"
          "                      than that\n"
          "  --seed N|random     override every case's seed (mixed with the case id; not pin_seed cases)\n"
          "  --alternative A     power run: the data generator (never the oracle) draws under\n"
          "                      A = KEY*FACTOR or KEY+DELTA, or 'scene': each case's power_alt\n"
          "  --tags A,B          only cases carrying at least one of these tags\n"
          "  --only TEXT         only cases whose id contains TEXT (repeatable)\n"
          "  --baseline FILE     compare with an older results.json: DIR/drift.md lists verdict\n"
          "                      changes, moved metrics and slower cases (never fails the run)\n"
          "  --list              list the selected cases with tier, kind, check and tags\n"
          "  --checks            list the registered checks\n"
          "  -h, --help          this help\n\n"
          "exit status: 0 all passed, 1 a case failed, 2 bad input or usage, 3 internal error,\n"
          "130 interrupted by SIGINT (Ctrl-C; SIGTERM 143): no summary is written\n",
          f);
}

static unsigned long mix_seed(unsigned long seed, const char *id)
{
    /* FNV-1a of the id, mixed with the override, so cases stay independent.
     * The start value is FNV's offset basis 14695981039346656037 without
     * its last digit (a slip made long ago): kept, so that a --seed run
     * draws the seeds it always drew. */
    return (sf_mc_hash(id, strlen(id), 1469598103934665603UL) ^ seed) & 0xffffffffUL;
}

/* Does the comma-separated list `have` contain any item of `want`? */
static int tags_match(const char *have, const char *want)
{
    const char *w = want;
    while (*w) {
        size_t wl = strcspn(w, ",");
        const char *h = have;
        while (*h) {
            size_t hl = strcspn(h, ",");
            if (hl == wl && wl > 0 && !strncmp(h, w, wl))
                return 1;
            h += hl + (h[hl] == ',');
        }
        w += wl + (w[wl] == ',');
    }
    return 0;
}

static int cmp_case(const void *a, const void *b)
{
    return strcmp(((const sf_case *)a)->id, ((const sf_case *)b)->id);
}

static void fill_outcome(sf_outcome *o, const sf_case *c)
{
    memset(o, 0, sizeof *o);
    snprintf(o->id, sizeof o->id, "%s", c->id);
    snprintf(o->family, sizeof o->family, "%s", c->family);
    snprintf(o->path, sizeof o->path, "%s", c->path);
    snprintf(o->title, sizeof o->title, "%s", c->title);
    o->tier = c->spec.tier;
    o->vv = c->spec.vv;
    o->seed = c->scene.seed;
    snprintf(o->check, sizeof o->check, "%s", c->spec.check);
    o->margin = NAN;
    sf_budget_entry_init(&o->budget, c);
}

/* Run the check; a case that failed only in suspect statistical rows
 * runs once more on a fresh stream and the replication's result replaces
 * the first (budget.h).  Records in *e the statistical rows of the result
 * kept.  Returns the check's status. */
static int run_check(const sf_case *c, const sf_check_def *d, sf_result **r, sf_budget_entry *e)
{
    int rc = d->fn(c, *r);
    if (!rc && sf_budget_suspect(c, *r)) {
        sf_case c2 = *c;   /* shallow: the check only reads it */
        c2.scene.seed = sf_budget_replica_seed(c->scene.seed);
        char note[2048];
        sf_budget_replica_note(*r, c->scene.seed, c2.scene.seed, note, sizeof note);
        sf_result_free(*r);
        *r = sf_result_alloc();
        sf_note(*r, "%s", note);
        e->replicated = 1;
        rc = d->fn(&c2, *r);
    }
    sf_budget_entry_rows(e, *r);
    return rc;
}

/* A case process ends with _exit (the parent's stdio buffers and atexit
 * handlers are not its own), which skips gcov's exit handler: in a
 * --coverage build (make coverage) the case's counts would be lost, and
 * the quick tier would add nothing to the coverage it is said to add.
 * libgcov's __gcov_dump writes them; the weak reference is NULL in every
 * other build. */
extern void __gcov_dump(void) __attribute__((weak));
static void child_exit(int code)
{
    if (__gcov_dump)
        __gcov_dump();
    _exit(code);
}

/* Child: run the check, write the report, send one line to the parent. */
static void run_child(const sf_case *c, const char *root, int fd, unsigned timeout, unsigned cpu_limit)
{
    /* die with the runner: a killed `make verify` leaves no case running
       on to write a report nobody asked for any more */
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() == 1)
        child_exit(SF_EXIT_INTERNAL);
    /* the wall limit never stops a case before it could have spent its
       CPU limit at full speed: on a loaded machine a long case's wall
       time grows many times (a paper-tier case measured at 5.7x), its CPU
       time does not (with --timeout, cpu_limit is 0: the wall limit alone) */
    alarm(cpu_limit > timeout ? cpu_limit : timeout);
    if (cpu_limit) {
        /* SIGXCPU at the limit, SIGKILL a little later if it is caught */
        struct rlimit rl = { cpu_limit, (rlim_t)cpu_limit + 5 };
        setrlimit(RLIMIT_CPU, &rl);
    }
    sf_outcome o;
    fill_outcome(&o, c);
    const sf_check_def *d = sf_check_find(c->spec.check);
    sf_result *r = sf_result_alloc();
    if (c->alternative[0])
        sf_note(r, "**Power run:** the data generator draws under the alternative `%s` (the oracle does not): "
                   "this run should FAIL.\n", c->alternative);
    double t0 = now();
    int rc = run_check(c, d, &r, &o.budget);
    o.seconds = now() - t0;
    size_t nrows = sf_result_nrows(r);   /* the check's own rows */
    /* the plots before the verdict: a misdrawn one is a failing row */
    char perr[256] = "";
    int prc = sf_report_plots(root, c, r, perr, sizeof perr);
    char msg[300] = "";
    if (rc) {
        snprintf(msg, sizeof msg, "the check could not complete: %s", sf_strerror(rc));
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "%s", msg);
    } else if (nrows == 0) {
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "the check produced no row (it cannot fail, so it cannot pass)");
    } else if (sf_result_nplots(r) == 0) {
        /* every case report shows its evidence: a check without a plot is
           a defect like a check without a row (docs/design.md sec. 7.6) */
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "the check produced no plot (a report must show its evidence)");
    } else if (prc != SF_SUCCESS) {
        snprintf(msg, sizeof msg, "plots not rendered: %s", perr);
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "%s", msg);
    } else {
        sf_result_gate_nonfinite(r);
        o.verdict = sf_result_passed(r) ? SF_VERDICT_PASS : SF_VERDICT_FAIL;
        const sf_row *k = sf_result_key_row(r);
        snprintf(o.key, sizeof o.key, "%s = %.4g (%s)", k->quantity, k->measured, k->criterion);
    }
    char err[512] = "";
    if (sf_report_case(root, c, r, &o, msg, err, sizeof err) != SF_SUCCESS) {
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "report not written: %.280s", err);
    }
    sf_result_free(r);
    char line[1024], be[96];
    sf_budget_entry_format(&o.budget, be, sizeof be);
    int n = snprintf(line, sizeof line, "%d\t%.6f\t%s\t%s\n", o.verdict, o.seconds, be, o.key);
    if (n > 0 && write(fd, line, (size_t)(n < (int)sizeof line ? n : (int)sizeof line - 1)) < 0)
        child_exit(SF_EXIT_INTERNAL);
    close(fd);
    child_exit(SF_EXIT_OK);
}

typedef struct {
    pid_t pid;
    int fd;
    size_t idx;
    double t0;
} job;

static void finish_job(const job *j, int status, const sf_case *cases, sf_outcome *out,
                       const char *root)
{
    unsigned cpu_limit;
    const sf_case *c = &cases[j->idx];
    sf_outcome *o = &out[j->idx];
    fill_outcome(o, c);
    char line[1024] = "";
    ssize_t n = read(j->fd, line, sizeof line - 1);
    close(j->fd);
    line[n > 0 ? n : 0] = '\0';
    int ok = 0;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && n > 0) {
        char *tab1 = strchr(line, '\t'), *tab2 = tab1 ? strchr(tab1 + 1, '\t') : NULL;
        char *tab3 = tab2 ? strchr(tab2 + 1, '\t') : NULL;
        if (tab3 && sf_budget_entry_scan(&o->budget, tab2 + 1)) {
            o->verdict = atoi(line);
            o->seconds = strtod(tab1 + 1, NULL);
            char *nl = strchr(tab3 + 1, '\n');
            if (nl) *nl = '\0';
            snprintf(o->key, sizeof o->key, "%s", tab3 + 1);
            ok = 1;
        }
    }
    if (!ok) {
        o->verdict = SF_VERDICT_ERROR;
        o->seconds = now() - j->t0;
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
            snprintf(o->key, sizeof o->key, "timed out after %.0f s", o->seconds);
        else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU && (cpu_limit = sf_casetime_limit(c->path, c->id)) > 0)
            snprintf(o->key, sizeof o->key, "stopped at its CPU-time limit of %u s (20x its recorded CPU time, at "
                     "least 60 s): a hang, or a case many times slower than it was", cpu_limit);
        else if (WIFSIGNALED(status))
            snprintf(o->key, sizeof o->key, "crashed with signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
        else
            snprintf(o->key, sizeof o->key, "exited with status %d before reporting", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        char err[256];
        sf_report_crash(root, c, o, err, sizeof err);
    }
    printf("%-5s %-48s %8.2f s  %s\n", sf_verdict_name(o->verdict), o->id, o->seconds, o->key);
    fflush(stdout);
}

/* ---- sf_verify_main in steps: options, cases, reports folder, runs,
 * summaries, exit status ---- */

/* What `slipfield verify` was asked to do. */
typedef struct {
    const char *root;
    int tier;                  /* --tier: 0 quick, 1 full (quick and full), 2 paper */
    int jobs, list, have_seed;
    unsigned timeout;          /* --timeout: wall-time limit of each case */
    int timeout_set;           /* --timeout given: no CPU-time limits */
    unsigned long seed;
    char seed_note[64];
    const char *tags, *baseline_path, *alternative;
    const char *only[16];
    int nonly;
} verify_opts;

static int opt_checks(const char *cmd, const char *v, void *dst)
{
    (void)cmd, (void)v, (void)dst;
    const sf_check_def *d;
    for (size_t k = 0; (d = sf_check_at(k)); k++)
        printf("%-36s %s\n", d->name, d->summary);
    return SF_EXIT_OK;
}

static int opt_only(const char *cmd, const char *v, void *dst)
{
    verify_opts *o = dst;
    if (o->nonly == 16) { fprintf(stderr, "slipfield %s: at most 16 --only\n", cmd); return SF_EXIT_USAGE; }
    o->only[o->nonly++] = v;
    return SF_EXIT_OK;
}

static int opt_tier(const char *cmd, const char *v, void *dst)
{
    int *tier = dst;
    if (!strcmp(v, "full")) *tier = 1;
    else if (!strcmp(v, "quick")) *tier = 0;
    else if (!strcmp(v, "paper")) *tier = 2;
    else { fprintf(stderr, "slipfield %s: --tier takes quick, full or paper, not '%s'\n", cmd, v); return SF_EXIT_USAGE; }
    return SF_EXIT_OK;
}

static int opt_jobs(const char *cmd, const char *v, void *dst)
{
    int *jobs = dst;
    *jobs = atoi(v);
    if (*jobs < 1 || *jobs > 64) { fprintf(stderr, "slipfield %s: --jobs takes 1..64\n", cmd); return SF_EXIT_USAGE; }
    return SF_EXIT_OK;
}

static int opt_timeout(const char *cmd, const char *v, void *dst)
{
    verify_opts *o = dst;
    o->timeout = (unsigned)atoi(v);
    o->timeout_set = 1;
    if (o->timeout < 1) { fprintf(stderr, "slipfield %s: --timeout takes seconds >= 1\n", cmd); return SF_EXIT_USAGE; }
    return SF_EXIT_OK;
}

/* A case's CPU-time limit (0: none): scaled from its recorded CPU time
 * (casetime.h), unless --timeout set a wall limit for every case (a run
 * under valgrind, say, which multiplies CPU time). */
static unsigned case_cpu_limit(const verify_opts *o, const sf_case *c)
{
    return o->timeout_set ? 0 : sf_casetime_limit(c->path, c->id);
}

static int opt_alternative(const char *cmd, const char *v, void *dst)
{
    sf_alt alt;
    char e2[160];
    if (strcmp(v, "scene") && sf_alt_parse(v, &alt, e2, sizeof e2)) {
        fprintf(stderr, "slipfield %s: --alternative: %s\n", cmd, e2);
        return SF_EXIT_USAGE;
    }
    *(const char **)dst = v;
    return SF_EXIT_OK;
}

static int opt_seed(const char *cmd, const char *v, void *dst)
{
    verify_opts *o = dst;
    o->have_seed = 1;
    if (!strcmp(v, "random")) {
        o->seed = (unsigned long)time(NULL) ^ ((unsigned long)getpid() << 16);
    } else {
        char *end;
        o->seed = strtoul(v, &end, 10);
        if (*end || !*v) { fprintf(stderr, "slipfield %s: --seed takes a number or 'random'\n", cmd); return SF_EXIT_USAGE; }
    }
    snprintf(o->seed_note, sizeof o->seed_note, "override %lu", o->seed);
    return SF_EXIT_OK;
}

/* Options, then the case files (files has room for argc entries). */
static int parse_options(int argc, char **argv, verify_opts *o, const char **files, size_t *n)
{
    *o = (verify_opts){ .root = "reports", .jobs = 1, .timeout = 900, .seed_note = "fixed (per case)" };
    const sf_opt opts[] = {
        { "--checks", SF_OPT_ACTION, NULL, 0, 0, opt_checks },
        { "--list", SF_OPT_FLAG, &o->list, 0, 0, NULL },
        { "--baseline", SF_OPT_STRING, &o->baseline_path, 0, 0, NULL },
        { "--tags", SF_OPT_STRING, &o->tags, 0, 0, NULL },
        { "--only", SF_OPT_FN, o, 0, 0, opt_only },
        { "--tier", SF_OPT_FN, &o->tier, 0, 0, opt_tier },
        { "--reports", SF_OPT_STRING, &o->root, 0, 0, NULL },
        { "--jobs", SF_OPT_FN, &o->jobs, 0, 0, opt_jobs },
        { "--timeout", SF_OPT_FN, o, 0, 0, opt_timeout },
        { "--alternative", SF_OPT_FN, &o->alternative, 0, 0, opt_alternative },
        { "--seed", SF_OPT_FN, o, 0, 0, opt_seed },
    };
    sf_optspec sp = { "verify", opts, sizeof opts / sizeof opts[0], usage, 0, NULL, "no case files given" };
    return sf_opt_parse(&sp, argc, argv, files, n);
}

static void free_cases(sf_case *cases, size_t n)
{
    for (size_t k = 0; k < n; k++) sf_case_free(&cases[k]);
    free(cases);
}

/* Is a read case selected by --tags and --only? */
static int wanted(const verify_opts *o, const sf_case *c)
{
    int want = !o->tags || tags_match(c->spec.tags, o->tags);
    if (o->nonly) {
        int any = 0;
        for (int q = 0; q < o->nonly; q++)
            any |= strstr(c->id, o->only[q]) != NULL;
        want &= any;
    }
    return want;
}

/* paper-tier cases (the paper's T = 100 s, 100 realisations: ~30 min)
   run only with --tier paper, which runs nothing else */
static int other_tier(const verify_opts *o, const sf_case *c)
{
    int tier = c->spec.tier;
    return o->tier == 2 ? tier != SF_TIER_PAPER : (tier == SF_TIER_PAPER || (tier == SF_TIER_FULL && !o->tier));
}

/* A selection that matches nothing is an error (a typo in a CI filter
 * must not give a green build): say which filter emptied it. */
static void no_case_selected(const verify_opts *o, size_t nread, size_t skipped)
{
    fprintf(stderr, "slipfield verify: no case selected: ");
    if (skipped)
        fprintf(stderr, "the %zu matching case%s belong%s to other tiers than --tier %s\n", skipped,
                skipped == 1 ? "" : "s", skipped == 1 ? "s" : "", o->tier == 2 ? "paper" : o->tier ? "full" : "quick");
    else {
        fprintf(stderr, "of the %zu case%s read, none matches", nread, nread == 1 ? "" : "s");
        if (o->tags)
            fprintf(stderr, " --tags %s", o->tags);
        for (int q = 0; q < o->nonly; q++)
            fprintf(stderr, "%s --only %s", q || o->tags ? "," : "", o->only[q]);
        fputc('\n', stderr);
    }
}

/* Read the case files, keep the selected ones (seed override and power
 * alternative applied), sorted by id.  Returns an exit status. */
static int select_cases(const verify_opts *o, const char **files, size_t n, sf_case **out, size_t *nkept,
                        size_t *nskipped)
{
    sf_case *cases = calloc(n, sizeof *cases);
    if (!cases)
        return SF_EXIT_INTERNAL;
    size_t kept = 0, skipped = 0;
    int bad = 0;
    for (size_t k = 0; k < n; k++) {
        char err[512];
        sf_case *c = &cases[kept];
        if (sf_case_read(c, files[k], err, sizeof err) != SF_SUCCESS) {
            fprintf(stderr, "slipfield verify: %s\n", err);
            sf_case_free(c);
            bad = 1;
            continue;
        }
        if (!wanted(o, c)) {
            sf_case_free(c);
            continue;
        }
        if (other_tier(o, c)) {
            sf_case_free(c);
            skipped++;
            continue;
        }
        /* a pinned case checks one realisation deterministically: a fresh
           seed would change the problem, not draw a fresh sample of a test */
        if (o->have_seed && !c->spec.pin_seed)
            c->scene.seed = mix_seed(o->seed, c->id);
        if (o->alternative)
            snprintf(c->alternative, sizeof c->alternative, "%s",
                     strcmp(o->alternative, "scene") ? o->alternative : c->spec.power_alt);
        kept++;
    }
    if (bad) {
        free_cases(cases, kept);
        return SF_EXIT_USAGE;
    }
    if (!kept) {
        no_case_selected(o, n, skipped);
        free(cases);
        return SF_EXIT_USAGE;
    }
    qsort(cases, kept, sizeof *cases, cmp_case);
    for (size_t k = 1; k < kept; k++)
        if (!strcmp(cases[k].id, cases[k - 1].id)) {
            fprintf(stderr, "slipfield verify: case %s given twice\n", cases[k].id);
            return SF_EXIT_USAGE;
        }
    *out = cases;
    *nkept = kept;
    *nskipped = skipped;
    return SF_EXIT_OK;
}

static void list_cases(const verify_opts *o, const sf_case *cases, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        printf("%-48s tier=%-5s ", cases[k].id, sf_case_enum_name("tier", cases[k].spec.tier));
        printf("vv=%-10s check=%s tags=%s cpu_limit=%us wall_limit=%us\n", sf_case_enum_name("vv", cases[k].spec.vv),
               cases[k].spec.check, cases[k].spec.tags, case_cpu_limit(o, &cases[k]), o->timeout);
    }
}

/* Create the report folder and remove what this run will rewrite.
 * Returns an exit status. */
static int clear_reports(const char *root, const sf_case *cases, size_t n)
{
    if (sf_mkdirs(root) != 0) {
        fprintf(stderr, "slipfield verify: cannot create %s: %s\n", root, strerror(errno));
        return SF_EXIT_INTERNAL;
    }
    /* A run that is killed must not leave the previous run's summary
     * claiming verdicts: remove it now, write the new one at the end. */
    static const char *summaries[] = { "index.md", "index.html", "junit.xml", "results.json",
                                       "drift.md", "drift.html", "paper.md", "paper.html" };
    for (size_t k = 0; k < sizeof summaries / sizeof *summaries; k++) {
        char p[1100];
        snprintf(p, sizeof p, "%s/%s", root, summaries[k]);
        unlink(p);
    }
    /* nor a selected case's old report: each is rewritten when (and only
     * when) this run reaches its verdict */
    for (size_t k = 0; k < n; k++) {
        static const char *files[] = { "report.md", "report.html", "result.json" };
        for (int f = 0; f < 3; f++) {
            char p[1100];
            snprintf(p, sizeof p, "%s/%s/%s", root, cases[k].id, files[f]);
            unlink(p);
        }
    }
    return SF_EXIT_OK;
}

/* Fork case `next` into a free slot of run[] (the child frees run, out
 * and order: the parent's).  Returns an exit status. */
static int spawn_case(const sf_case *cases, size_t next, const verify_opts *o, job *run, sf_outcome *out,
                      size_t *order)
{
    int fd[2];
    if (pipe(fd) != 0) {
        perror("slipfield verify: pipe");
        return SF_EXIT_INTERNAL;
    }
    pid_t pid = fork();
    if (pid < 0) {
        perror("slipfield verify: fork");
        return SF_EXIT_INTERNAL;
    }
    if (pid == 0) {
        close(fd[0]);
        /* the parent's bookkeeping is not the child's: free it so
           a leak check of the case process sees only its own */
        free(run);
        free(out);
        free(order);
        run_child(&cases[next], o->root, fd[1], o->timeout, case_cpu_limit(o, &cases[next]));
    }
    close(fd[1]);
    for (int s = 0; s < o->jobs; s++)
        if (run[s].pid == 0) {
            run[s] = (job){ pid, fd[0], next, now() };
            break;
        }
    return SF_EXIT_OK;
}

/* CPU seconds of the children reaped since *prev (then *prev = now). */
static double children_cpu(struct rusage *prev)
{
    struct rusage ru;
    getrusage(RUSAGE_CHILDREN, &ru);
    double cpu = (double)(ru.ru_utime.tv_sec - prev->ru_utime.tv_sec + ru.ru_stime.tv_sec - prev->ru_stime.tv_sec) +
                 1e-6 * (double)(ru.ru_utime.tv_usec - prev->ru_utime.tv_usec + ru.ru_stime.tv_usec - prev->ru_stime.tv_usec);
    *prev = ru;
    return cpu;
}

typedef struct { double t; size_t k; } case_order;

static int cmp_order(const void *a, const void *b)
{
    const case_order *x = a, *y = b;
    return x->t > y->t ? -1 : x->t < y->t ? 1 : (x->k > y->k) - (x->k < y->k);
}

/* The order to start the cases in: with more than one slot, longest
 * recorded CPU time first (a case with none first of all: it may be
 * long), so that the run does not end on one long case while the other
 * slots idle; with one, the cases' own (id) order.  Each case's seed
 * comes from its id, so the order changes no result. */
static size_t *start_order(const sf_case *cases, size_t n, int jobs)
{
    case_order *t = malloc((n ? n : 1) * sizeof *t);
    size_t *order = malloc((n ? n : 1) * sizeof *order);
    if (!t || !order) {
        free(t);
        free(order);
        return NULL;
    }
    for (size_t k = 0; k < n; k++) {
        double rec = jobs > 1 ? sf_casetime_recorded(cases[k].path, cases[k].id) : 0;
        t[k] = (case_order){ rec < 0 ? INFINITY : rec, k };
    }
    qsort(t, n, sizeof *t, cmp_order);
    for (size_t k = 0; k < n; k++)
        order[k] = t[k].k;
    free(t);
    return order;
}

/* Run the cases, o->jobs at a time, each in its own process; out[k] gets
 * case k's outcome.  Returns an exit status. */
static int run_cases(const sf_case *cases, size_t kept, const verify_opts *o, sf_outcome *out, job *run)
{
    size_t next = 0, active = 0;
    size_t *order = start_order(cases, kept, o->jobs);
    if (!order)
        return SF_EXIT_INTERNAL;
    /* CPU time of each case process (and of the gnuplot it ran): the
     * growth of RUSAGE_CHILDREN across the wait() that reaped it.  Unlike
     * wall time it hardly depends on what else the machine runs, so the
     * drift page compares it. */
    struct rusage ru_prev;
    getrusage(RUSAGE_CHILDREN, &ru_prev);
    while (next < kept || active > 0) {
        for (; next < kept && active < (size_t)o->jobs; next++, active++)
            if (spawn_case(cases, order[next], o, run, out, order)) {
                free(order);
                return SF_EXIT_INTERNAL;
            }
        int status;
        pid_t pid = wait(&status);
        if (pid < 0) {
            if (errno == EINTR) continue;
            break;
        }
        double cpu = children_cpu(&ru_prev);
        for (int s = 0; s < o->jobs; s++)
            if (run[s].pid == pid) {
                finish_job(&run[s], status, cases, out, o->root);
                out[run[s].idx].cpu_seconds = cpu;
                run[s].pid = 0;
                active--;
                break;
            }
    }
    free(order);
    return SF_EXIT_OK;
}

static void print_drift(const sf_drift_summary *drift, const char *baseline_path, const char *root)
{
    if (sf_drift_any(drift))
        printf("drift: %zu verdict change%s (%zu to FAIL or ERROR), %zu metric%s moved, %zu run time%s grew, "
               "%zu case%s added, %zu removed: %s/drift.html\n", drift->verdicts, drift->verdicts == 1 ? "" : "s",
               drift->to_fail, drift->moved, drift->moved == 1 ? "" : "s", drift->slower,
               drift->slower == 1 ? "" : "s", drift->added, drift->added == 1 ? "" : "s", drift->removed, root);
    else
        printf("drift: none against %s (%s/drift.html)\n", baseline_path, root);
}

/* results.json, drift page, index (md, html), JUnit, paper page; the
 * baseline is freed.  Returns nonzero when one could not be written. */
static int write_summaries(sf_run_meta *meta, const verify_opts *o, sf_outcome *out, size_t kept,
                           sf_baseline *baseline)
{
    char err[512];
    int rc = sf_results_write(meta, out, kept, o->baseline_path, err, sizeof err);
    sf_drift_summary drift;
    if (!rc && baseline) {
        rc = sf_drift_write(baseline, o->root, &drift, err, sizeof err);
        if (!rc)
            meta->drift = &drift;
    }
    sf_baseline_free(baseline);
    if (rc)
        fprintf(stderr, "slipfield verify: %s\n", err);
    int rc2 = sf_report_index(meta, out, kept, err, sizeof err);
    if (!rc2 && (rc2 = sf_paper_report(meta, out, kept, err, sizeof err)) == 0 && o->tier == 2)
        printf("the paper's claims: %s/paper.md, %s/paper.html\n", o->root, o->root);
    if (rc2)
        fprintf(stderr, "slipfield verify: %s\n", err);
    const char *root = o->root;
    printf("reports: %s/index.html, %s/index.md, %s/junit.xml, %s/results.json\n", root, root, root, root);
    if (meta->drift)
        print_drift(&drift, o->baseline_path, root);
    meta->drift = NULL;   /* it pointed here */
    return rc ? rc : rc2;
}

/* Run the selected cases and write every summary.  Returns the exit status. */
static int run_and_report(const verify_opts *o, const sf_case *cases, size_t kept, size_t skipped,
                          sf_baseline *baseline)
{
    if (skipped)
        printf("(%zu cases of other tiers skipped; run with TIER=full or TIER=paper)\n", skipped);
    sf_outcome *out = calloc(kept ? kept : 1, sizeof *out);
    job *run = calloc((size_t)o->jobs, sizeof *run);
    if (!out || !run)
        return SF_EXIT_INTERNAL;
    fflush(stdout);
    double t0 = now();
    if (run_cases(cases, kept, o, out, run))
        return SF_EXIT_INTERNAL;
    size_t np = 0, nf = 0;
    for (size_t k = 0; k < kept; k++) {
        if (out[k].verdict == SF_VERDICT_PASS) np++;
        else nf++;
    }
    sf_run_meta meta = { o->root, o->seed_note, o->tier == 2 ? "paper" : o->tier ? "full" : "quick", now() - t0,
                         skipped, NULL };
    int rc = write_summaries(&meta, o, out, kept, baseline);
    printf("%zu passed, %zu failed\n", np, nf);
    free(out);
    free(run);
    if (rc)
        return SF_EXIT_INTERNAL;
    return nf ? SF_EXIT_CHECK : SF_EXIT_OK;
}

/* The selected cases, also from file scope: a forked case process
 * _exits without unwinding, and the array must stay reachable there (an
 * optimised frame may keep the only pointer in a register it reused). */
static sf_case *volatile selected;   /* volatile: the store is kept though nothing reads it */

int sf_verify_main(int argc, char **argv)
{
    verify_opts o;
    const char **files = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *files);
    if (!files)
        return SF_EXIT_INTERNAL;
    size_t n, kept = 0, skipped = 0;
    sf_case *cases = NULL;
    int rc = parse_options(argc, argv, &o, files, &n);
    if (!rc)
        rc = select_cases(&o, files, n, &cases, &kept, &skipped);
    selected = cases;
    free(files);
    if (rc)
        return rc == SF_OPT_DONE ? SF_EXIT_OK : rc;
    if (o.list) {
        list_cases(&o, cases, kept);
        free_cases(cases, kept);
        return SF_EXIT_OK;
    }
    /* the baseline is read now: this run may be about to overwrite it */
    sf_baseline *baseline = NULL;
    if (o.baseline_path) {
        char err[700];
        if (sf_baseline_load(o.baseline_path, &baseline, err, sizeof err) != SF_SUCCESS) {
            fprintf(stderr, "slipfield verify: %s\n", err);
            free_cases(cases, kept);
            return SF_EXIT_USAGE;
        }
    }
    rc = clear_reports(o.root, cases, kept);
    if (!rc)
        rc = run_and_report(&o, cases, kept, skipped, baseline);   /* frees the baseline */
    else
        sf_baseline_free(baseline);
    free_cases(cases, kept);
    return rc;
}
