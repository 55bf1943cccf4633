/* The tier's false-alarm budget: the ledger, and the replication of a
 * case whose only failures are suspect statistical rows (budget.h). */
#include "budget.h"
#include "montecarlo.h"
#include "report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sf_budget_entry_init(sf_budget_entry *e, const sf_case *c)
{
    memset(e, 0, sizeof *e);
    e->alpha = sf_case_spec_declared_alpha(&c->spec);
    e->kind = c->spec.pin_seed ? SF_BUDGET_PINNED : e->alpha > 0 ? SF_BUDGET_STAT
            : c->spec.seed_proof[0] ? SF_BUDGET_SEED_PROOF : SF_BUDGET_NONE;
    e->replicate = c->spec.replicate && e->alpha > 0;
}

void sf_budget_entry_rows(sf_budget_entry *e, const sf_result *r)
{
    e->nstat = 0;
    e->row_alpha = 0;
    for (size_t i = 0; i < sf_result_nrows(r); i++) {
        const sf_row *row = sf_result_row(r, i);
        if (row->alpha > 0) {
            e->nstat++;
            e->row_alpha += row->alpha;
        }
    }
    if (e->nstat && e->kind != SF_BUDGET_PINNED)
        e->kind = SF_BUDGET_STAT;
}

double sf_budget_share(const sf_budget_entry *e)
{
    if (e->kind == SF_BUDGET_PINNED)
        return 0;
    double A = e->row_alpha, a = fmax(e->alpha, A);
    /* `replicate`: the deterministic part too fails only if the
     * replication, an independent run, fails as well (at most a) */
    return (a - A) * (e->replicate ? a : 1) + SF_BUDGET_FLOOR * A + A * a;
}

int sf_budget_suspect(const sf_case *c, const sf_result *r)
{
    if (c->spec.pin_seed || sf_result_nonfinite(r) || sf_result_passed(r))
        return 0;
    for (size_t i = 0; i < sf_result_nrows(r); i++) {
        const sf_row *row = sf_result_row(r, i);
        if (row->pass)
            continue;
        if (!(row->alpha > 0)) {
            if (c->spec.replicate && sf_case_spec_declared_alpha(&c->spec) > 0)
                continue;   /* a tolerance on seed-dependent data, at the declared rate */
            return 0;   /* a failing row that is not statistical: no second chance */
        }
        if (row->test == SF_ROW_PVALUE && !(row->measured >= SF_BUDGET_FLOOR * row->alpha))
            return 0;   /* below the floor (or NaN): fails at once */
    }
    return 1;
}

unsigned long sf_budget_replica_seed(unsigned long seed)
{
    /* FNV-1a of the seed's decimal digits from another start value: a
     * stream unrelated to the first and the same on every machine */
    char s[32];
    int n = snprintf(s, sizeof s, "replica:%lu", seed);
    return sf_mc_hash(s, (size_t)n, 1099511628211UL) & 0xffffffffUL;
}

void sf_budget_replica_note(const sf_result *first, unsigned long seed, unsigned long seed2, char *buf, size_t len)
{
    size_t k = (size_t)snprintf(buf, len,
                                "**Replication.** At seed %lu only rows a replication may confirm failed (statistical "
                                "rows none below %g x its alpha, the suspect band; with `replicate`, tolerances on "
                                "seed-dependent data):", seed, SF_BUDGET_FLOOR);
    for (size_t i = 0; i < sf_result_nrows(first) && k < len; i++) {
        const sf_row *row = sf_result_row(first, i);
        if (!row->pass)
            k += (size_t)snprintf(buf + k, len - k, " %.80s = %.3g (%s);", row->quantity, row->measured, row->criterion);
    }
    if (k < len)
        snprintf(buf + k, len - k, " the case was run once more on a fresh stream (seed %lu), and this report is "
                                   "that run's: it fails only if the replication fails too.\n", seed2);
}

void sf_budget_entry_format(const sf_budget_entry *e, char *buf, size_t len)
{
    snprintf(buf, len, "%zu %.17g %d", e->nstat, e->row_alpha, e->replicated);
}

int sf_budget_entry_scan(sf_budget_entry *e, const char *s)
{
    return sscanf(s, "%zu %lg %d", &e->nstat, &e->row_alpha, &e->replicated) == 3;
}

static const char *kind_text(int kind)
{
    switch (kind) {
    case SF_BUDGET_STAT: return "statistical";
    case SF_BUDGET_SEED_PROOF: return "seed-proof";
    case SF_BUDGET_PINNED: return "pinned seed";
    default: return "no random data declared";
    }
}

void sf_budget_index_section(FILE *f, const char *tier_name, const sf_outcome *o, size_t n, const char *page)
{
    double sum = 0, sum_alpha = 0;
    size_t nstat = 0, nproof = 0, npin = 0, nnone = 0, nrep = 0;
    for (size_t i = 0; i < n; i++) {
        const sf_budget_entry *e = &o[i].budget;
        if (e->kind == SF_BUDGET_STAT) {
            nstat++;
            sum += sf_budget_share(e);
            sum_alpha += fmax(e->alpha, e->row_alpha);
        }
        nproof += e->kind == SF_BUDGET_SEED_PROOF;
        npin += e->kind == SF_BUDGET_PINNED;
        nnone += e->kind == SF_BUDGET_NONE;
        nrep += e->replicated != 0;
    }
    fprintf(f, "\n## False-alarm budget\n\n");
    fprintf(f, "One run of the %s tier at fresh seeds (`--seed random`) fails, when the code is right, with "
               "probability at most the sum of the cases' shares (Bonferroni over every case and row). "
               "**Budget %g; spent %.3g** by %zu statistical case%s: %s. A case's alpha is its own family-wise rate "
               "(split over its rows); a statistical row whose p-value is below its alpha but not below %g x it is "
               "*suspect* and the case is run once more on a fresh stream, failing only if that fails too; so a "
               "case spends share = (a - A) + %g A + A a, where A is the alpha of its statistical rows and a = "
               "max(alpha, A), or (a - A) a + %g A + A a when it sets `replicate` (a failure of its deterministic "
               "rows, a tolerance on seed-dependent data at a measured rate, is confirmed on a fresh stream too); "
               "a row that compares a Bonferroni-adjusted p-value with the case's alpha counts that alpha in "
               "full (conservative). Without the replication the same cases would spend %.3g. %zu case%s seed-proof "
               "(`seed_proof`: the tolerance holds at every seed), %zu pinned (`pin_seed`), %zu declare no random "
               "data (the false-alarm study, `make verify SEED=random REPEAT=N`, lists any that draw some). "
               "%zu case%s replicated in this run.\n\n",
            tier_name, SF_BUDGET_TIER, sum, nstat, nstat == 1 ? "" : "s",
            sum <= SF_BUDGET_TIER ? "within the budget" : "**over the budget**", SF_BUDGET_FLOOR, SF_BUDGET_FLOOR,
            SF_BUDGET_FLOOR, sum_alpha, nproof, nproof == 1 ? " is" : "s are", npin, nnone, nrep,
            nrep == 1 ? " was" : "s were");
    fprintf(f, "| case | budget | statistical rows | their alpha (sum) | case alpha | share | replicated |\n"
               "|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < n; i++) {
        const sf_budget_entry *e = &o[i].budget;
        if (e->kind != SF_BUDGET_STAT)
            continue;
        fprintf(f, "| [%s](%s/%s) | %s%s | %zu | %.3g | %.3g | %.3g | %s |\n", o[i].id, o[i].id, page,
                kind_text(e->kind), e->replicate ? " (replicate)" : "", e->nstat, e->row_alpha, e->alpha,
                sf_budget_share(e), e->replicated ? "**yes**" : "no");
    }
    fprintf(f, "| **sum** | | | | %.3g | **%.3g** (budget %g) | |\n", sum_alpha, sum, SF_BUDGET_TIER);
}
