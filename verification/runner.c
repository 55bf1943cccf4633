/* slipfield verify: run cases, each in its own process (a crash, abort or
 * time-out in one is that case's failure and the rest still run), write
 * the reports and gate on the verdicts. */
#include "runner.h"
#include "case.h"
#include "drift.h"
#include "registry.h"
#include "paper.h"
#include "report.h"
#include "result.h"
#include "results.h"
#include "montecarlo.h"
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
          "  --timeout S         per-case time limit in seconds (default 900)\n"
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
          "exit status: 0 all passed, 1 a case failed, 2 bad input or usage, 3 internal error\n",
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
}

/* Child: run the check, write the report, send one line to the parent. */
static void run_child(const sf_case *c, const char *root, int fd, unsigned timeout)
{
    /* die with the runner: a killed `make verify` leaves no case running
       on to write a report nobody asked for any more */
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() == 1)
        _exit(SF_EXIT_INTERNAL);
    alarm(timeout);
    sf_outcome o;
    fill_outcome(&o, c);
    const sf_check_def *d = sf_check_find(c->spec.check);
    sf_result *r = sf_result_alloc();
    if (c->alternative[0])
        sf_note(r, "**Power run:** the data generator draws under the alternative `%s` (the oracle does not): "
                   "this run should FAIL.\n", c->alternative);
    double t0 = now();
    int rc = d->fn(c, r);
    o.seconds = now() - t0;
    char msg[256] = "";
    if (rc) {
        snprintf(msg, sizeof msg, "the check could not complete: %s", sf_strerror(rc));
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "%s", msg);
    } else if (sf_result_nrows(r) == 0) {
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "the check produced no row (it cannot fail, so it cannot pass)");
    } else if (sf_result_nplots(r) == 0) {
        /* every case report shows its evidence: a check without a plot is
           a defect like a check without a row (issue 16) */
        o.verdict = SF_VERDICT_ERROR;
        snprintf(o.key, sizeof o.key, "the check produced no plot (a report must show its evidence)");
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
    char line[512];
    int n = snprintf(line, sizeof line, "%d\t%.6f\t%s\n", o.verdict, o.seconds, o.key);
    if (n > 0 && write(fd, line, (size_t)(n < (int)sizeof line ? n : (int)sizeof line - 1)) < 0)
        _exit(SF_EXIT_INTERNAL);
    close(fd);
    _exit(SF_EXIT_OK);
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
    const sf_case *c = &cases[j->idx];
    sf_outcome *o = &out[j->idx];
    fill_outcome(o, c);
    char line[600] = "";
    ssize_t n = read(j->fd, line, sizeof line - 1);
    close(j->fd);
    line[n > 0 ? n : 0] = '\0';
    int ok = 0;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && n > 0) {
        char *tab1 = strchr(line, '\t'), *tab2 = tab1 ? strchr(tab1 + 1, '\t') : NULL;
        if (tab1 && tab2) {
            o->verdict = atoi(line);
            o->seconds = strtod(tab1 + 1, NULL);
            char *nl = strchr(tab2 + 1, '\n');
            if (nl) *nl = '\0';
            snprintf(o->key, sizeof o->key, "%s", tab2 + 1);
            ok = 1;
        }
    }
    if (!ok) {
        o->verdict = SF_VERDICT_ERROR;
        o->seconds = now() - j->t0;
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
            snprintf(o->key, sizeof o->key, "timed out after %.0f s", o->seconds);
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

int sf_verify_main(int argc, char **argv)
{
    const char *root = "reports";
    int tier_full = 0, jobs = 1, list = 0, have_seed = 0;
    unsigned timeout = 900;
    unsigned long seed = 0;
    char seed_note[64] = "fixed (per case)";
    const char *tags = NULL, *only[16], *baseline_path = NULL, *alternative = NULL;
    int nonly = 0;
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return SF_EXIT_OK;
        } else if (!strcmp(a, "--checks")) {
            const sf_check_def *d;
            for (size_t k = 0; (d = sf_check_at(k)); k++)
                printf("%-36s %s\n", d->name, d->summary);
            return SF_EXIT_OK;
        } else if (!strcmp(a, "--list")) {
            list = 1;
        } else if (!strcmp(a, "--baseline") && v) {
            baseline_path = v;
            i++;
        } else if (!strcmp(a, "--tags") && v) {
            tags = v;
            i++;
        } else if (!strcmp(a, "--only") && v) {
            if (nonly == 16) { fprintf(stderr, "slipfield verify: at most 16 --only\n"); return SF_EXIT_USAGE; }
            only[nonly++] = v;
            i++;
        } else if (!strcmp(a, "--tier") && v) {
            if (!strcmp(v, "full")) tier_full = 1;
            else if (!strcmp(v, "quick")) tier_full = 0;
            else if (!strcmp(v, "paper")) tier_full = 2;
            else { fprintf(stderr, "slipfield verify: --tier takes quick, full or paper, not '%s'\n", v); return SF_EXIT_USAGE; }
            i++;
        } else if (!strcmp(a, "--reports") && v) {
            root = v;
            i++;
        } else if (!strcmp(a, "--jobs") && v) {
            jobs = atoi(v);
            if (jobs < 1 || jobs > 64) { fprintf(stderr, "slipfield verify: --jobs takes 1..64\n"); return SF_EXIT_USAGE; }
            i++;
        } else if (!strcmp(a, "--timeout") && v) {
            timeout = (unsigned)atoi(v);
            if (timeout < 1) { fprintf(stderr, "slipfield verify: --timeout takes seconds >= 1\n"); return SF_EXIT_USAGE; }
            i++;
        } else if (!strcmp(a, "--alternative") && v) {
            sf_alt alt;
            char e2[160];
            if (strcmp(v, "scene") && sf_alt_parse(v, &alt, e2, sizeof e2)) {
                fprintf(stderr, "slipfield verify: --alternative: %s\n", e2);
                return 2;
            }
            alternative = v;
            i++;
        } else if (!strcmp(a, "--seed") && v) {
            have_seed = 1;
            if (!strcmp(v, "random")) {
                seed = (unsigned long)time(NULL) ^ ((unsigned long)getpid() << 16);
            } else {
                char *end;
                seed = strtoul(v, &end, 10);
                if (*end || !*v) { fprintf(stderr, "slipfield verify: --seed takes a number or 'random'\n"); return SF_EXIT_USAGE; }
            }
            snprintf(seed_note, sizeof seed_note, "override %lu", seed);
            i++;
        } else {
            fprintf(stderr, "slipfield verify: unknown option or missing value: %s\n", a);
            usage(stderr);
            return SF_EXIT_USAGE;
        }
    }
    size_t n = (size_t)(argc - i);
    if (n == 0) {
        fprintf(stderr, "slipfield verify: no case files given\n");
        usage(stderr);
        return SF_EXIT_USAGE;
    }
    sf_case *cases = calloc(n, sizeof *cases);
    if (!cases)
        return SF_EXIT_INTERNAL;
    size_t kept = 0, skipped = 0;
    int bad = 0;
    for (size_t k = 0; k < n; k++) {
        char err[512];
        if (sf_case_read(&cases[kept], argv[i + (int)k], err, sizeof err) != SF_SUCCESS) {
            fprintf(stderr, "slipfield verify: %s\n", err);
            sf_case_free(&cases[kept]);
            bad = 1;
            continue;
        }
        int want = !tags || tags_match(cases[kept].spec.tags, tags);
        if (nonly) {
            int any = 0;
            for (int q = 0; q < nonly; q++)
                any |= strstr(cases[kept].id, only[q]) != NULL;
            want &= any;
        }
        if (!want) {
            sf_case_free(&cases[kept]);
            continue;
        }
        /* paper-tier cases (the paper's T = 100 s, 100 realisations: ~30 min)
           run only with --tier paper, which runs nothing else */
        int tier = cases[kept].spec.tier;
        if (tier_full == 2 ? tier != SF_TIER_PAPER : (tier == SF_TIER_PAPER || (tier == SF_TIER_FULL && !tier_full))) {
            sf_case_free(&cases[kept]);
            skipped++;
            continue;
        }
        /* a pinned case checks one realisation deterministically: a fresh
           seed would change the problem, not draw a fresh sample of a test */
        if (have_seed && !cases[kept].spec.pin_seed)
            cases[kept].scene.seed = mix_seed(seed, cases[kept].id);
        if (alternative)
            snprintf(cases[kept].alternative, sizeof cases[kept].alternative, "%s",
                     strcmp(alternative, "scene") ? alternative : cases[kept].spec.power_alt);
        kept++;
    }
    if (bad) {
        for (size_t k = 0; k < kept; k++) sf_case_free(&cases[k]);
        free(cases);
        return SF_EXIT_USAGE;
    }
    qsort(cases, kept, sizeof *cases, cmp_case);
    for (size_t k = 1; k < kept; k++)
        if (!strcmp(cases[k].id, cases[k - 1].id)) {
            fprintf(stderr, "slipfield verify: case %s given twice\n", cases[k].id);
            return SF_EXIT_USAGE;
        }
    if (list) {
        for (size_t k = 0; k < kept; k++)
        {
            printf("%-48s tier=%-5s ", cases[k].id, sf_case_enum_name("tier", cases[k].spec.tier));
            printf("vv=%-10s check=%s tags=%s\n", sf_case_enum_name("vv", cases[k].spec.vv), cases[k].spec.check,
                   cases[k].spec.tags);
        }
        for (size_t k = 0; k < kept; k++) sf_case_free(&cases[k]);
        free(cases);
        return SF_EXIT_OK;
    }
    /* the baseline is read now: this run may be about to overwrite it */
    sf_baseline *baseline = NULL;
    if (baseline_path) {
        char err[700];
        if (sf_baseline_load(baseline_path, &baseline, err, sizeof err) != SF_SUCCESS) {
            fprintf(stderr, "slipfield verify: %s\n", err);
            for (size_t k = 0; k < kept; k++) sf_case_free(&cases[k]);
            free(cases);
            return SF_EXIT_USAGE;
        }
    }
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
    for (size_t k = 0; k < kept; k++) {
        static const char *files[] = { "report.md", "report.html", "result.json" };
        for (int f = 0; f < 3; f++) {
            char p[1100];
            snprintf(p, sizeof p, "%s/%s/%s", root, cases[k].id, files[f]);
            unlink(p);
        }
    }
    if (skipped)
        printf("(%zu cases of other tiers skipped; run with TIER=full or TIER=paper)\n", skipped);

    sf_outcome *out = calloc(kept ? kept : 1, sizeof *out);
    job *run = calloc((size_t)jobs, sizeof *run);
    if (!out || !run)
        return SF_EXIT_INTERNAL;
    fflush(stdout);
    double t0 = now();
    size_t next = 0, active = 0;
    /* CPU time of each case process (and of the gnuplot it ran): the
     * growth of RUSAGE_CHILDREN across the wait() that reaped it.  Unlike
     * wall time it hardly depends on what else the machine runs, so the
     * drift page compares it. */
    struct rusage ru_prev;
    getrusage(RUSAGE_CHILDREN, &ru_prev);
    while (next < kept || active > 0) {
        while (next < kept && active < (size_t)jobs) {
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
                run_child(&cases[next], root, fd[1], timeout);
            }
            close(fd[1]);
            for (int s = 0; s < jobs; s++)
                if (run[s].pid == 0) {
                    run[s] = (job){ pid, fd[0], next, now() };
                    break;
                }
            next++;
            active++;
        }
        int status;
        pid_t pid = wait(&status);
        if (pid < 0) {
            if (errno == EINTR) continue;
            break;
        }
        struct rusage ru;
        getrusage(RUSAGE_CHILDREN, &ru);
        double cpu = (double)(ru.ru_utime.tv_sec - ru_prev.ru_utime.tv_sec + ru.ru_stime.tv_sec - ru_prev.ru_stime.tv_sec) +
                     1e-6 * (double)(ru.ru_utime.tv_usec - ru_prev.ru_utime.tv_usec + ru.ru_stime.tv_usec - ru_prev.ru_stime.tv_usec);
        ru_prev = ru;
        for (int s = 0; s < jobs; s++)
            if (run[s].pid == pid) {
                finish_job(&run[s], status, cases, out, root);
                out[run[s].idx].cpu_seconds = cpu;
                run[s].pid = 0;
                active--;
                break;
            }
    }
    size_t np = 0, nf = 0;
    for (size_t k = 0; k < kept; k++) {
        if (out[k].verdict == SF_VERDICT_PASS) np++;
        else nf++;
    }
    sf_run_meta meta = { root, seed_note, tier_full == 2 ? "paper" : tier_full ? "full" : "quick", now() - t0, skipped, NULL };
    char err[512];
    int rc = sf_results_write(&meta, out, kept, baseline_path, err, sizeof err);
    sf_drift_summary drift;
    if (!rc && baseline) {
        rc = sf_drift_write(baseline, root, &drift, err, sizeof err);
        if (!rc)
            meta.drift = &drift;
    }
    sf_baseline_free(baseline);
    if (rc)
        fprintf(stderr, "slipfield verify: %s\n", err);
    int rc2 = sf_report_index(&meta, out, kept, err, sizeof err);
    if (!rc2 && (rc2 = sf_paper_report(&meta, out, kept, err, sizeof err)) == 0 && tier_full == 2)
        printf("the paper's claims: %s/paper.md, %s/paper.html\n", root, root);
    if (rc2)
        fprintf(stderr, "slipfield verify: %s\n", err);
    rc = rc ? rc : rc2;
    printf("reports: %s/index.html, %s/index.md, %s/junit.xml, %s/results.json\n", root, root, root, root);
    if (meta.drift) {
        if (sf_drift_any(&drift))
            printf("drift: %zu verdict change%s (%zu to FAIL or ERROR), %zu metric%s moved, %zu run time%s grew, "
                   "%zu case%s added, %zu removed: %s/drift.html\n", drift.verdicts, drift.verdicts == 1 ? "" : "s",
                   drift.to_fail, drift.moved, drift.moved == 1 ? "" : "s", drift.slower,
                   drift.slower == 1 ? "" : "s", drift.added, drift.added == 1 ? "" : "s", drift.removed, root);
        else
            printf("drift: none against %s (%s/drift.html)\n", baseline_path, root);
    }
    printf("%zu passed, %zu failed\n", np, nf);
    for (size_t k = 0; k < kept; k++) sf_case_free(&cases[k]);
    free(cases);
    free(out);
    free(run);
    if (rc)
        return SF_EXIT_INTERNAL;
    return nf ? SF_EXIT_CHECK : SF_EXIT_OK;
}
