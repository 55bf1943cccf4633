/* A case's prose split into the parts its report shows, in order (prose.h:
 * the labels it reads, and History moved last). */
#include "prose.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { B_PARA, B_CONT, B_HEAD, B_FENCE };
enum { D_REST, D_CLAIM, D_WHY, D_TEST, D_TOL, D_HIST, D_DROP };

typedef struct {
    const char *s;
    size_t n;       /* without the last newline */
    int kind, level, after, dest;
} block;

typedef struct {
    block *b;
    size_t n, cap;
} blocks;

static int push(blocks *v, const char *s, size_t n, int kind, int level, int after)
{
    while (n && (s[n - 1] == '\n' || s[n - 1] == '\r'))
        n--;
    if (!n)
        return 0;
    if (v->n == v->cap) {
        size_t cap = v->cap ? 2 * v->cap : 32;
        block *b = realloc(v->b, cap * sizeof *b);
        if (!b)
            return -1;
        v->b = b;
        v->cap = cap;
    }
    v->b[v->n++] = (block){ s, n, kind, level, after, D_REST };
    return 0;
}

static int is_blank(const char *l, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isspace((unsigned char)l[i]))
            return 0;
    return 1;
}

static int is_fence(const char *l, size_t n)
{
    size_t i = 0;
    while (i < n && i < 3 && l[i] == ' ')
        i++;
    return n - i >= 3 && (!strncmp(l + i, "```", 3) || !strncmp(l + i, "~~~", 3));
}

/* the heading's level (1-6), or 0 */
static int heading_level(const char *l, size_t n)
{
    int k = 0;
    while ((size_t)k < n && l[k] == '#')
        k++;
    return k >= 1 && k <= 6 && (size_t)k < n && l[k] == ' ' ? k : 0;
}

/* a list item or an indented line: a continuation of the block before */
static int is_cont(const char *l, size_t n)
{
    if (n && (l[0] == ' ' || l[0] == '\t'))
        return 1;
    if (n >= 2 && (l[0] == '-' || l[0] == '*' || l[0] == '+') && l[1] == ' ')
        return 1;
    size_t i = 0;
    while (i < n && isdigit((unsigned char)l[i]))
        i++;
    return i && i + 1 < n && (l[i] == '.' || l[i] == ')') && l[i + 1] == ' ';
}

static int split_blocks(blocks *v, const char *text, int after)
{
    if (!text)
        return 0;
    const char *cur = NULL;   /* the open block's start */
    int kind = B_PARA, fence = 0;
    for (const char *l = text; *l;) {
        const char *nl = strchr(l, '\n');
        size_t n = nl ? (size_t)(nl - l) : strlen(l);
        const char *next = nl ? nl + 1 : l + n;
        if (fence) {
            if (is_fence(l, n)) {
                if (push(v, cur, (size_t)(next - cur), B_FENCE, 0, after))
                    return -1;
                cur = NULL;
                fence = 0;
            }
        } else if (is_blank(l, n)) {
            if (cur && push(v, cur, (size_t)(l - cur), kind, 0, after))
                return -1;
            cur = NULL;
        } else if (is_fence(l, n) || heading_level(l, n)) {
            if (cur && push(v, cur, (size_t)(l - cur), kind, 0, after))
                return -1;
            cur = NULL;
            if (is_fence(l, n)) {
                cur = l;
                fence = 1;
            } else if (push(v, l, n, B_HEAD, heading_level(l, n), after)) {
                return -1;
            }
        } else if (!cur) {
            cur = l;
            kind = is_cont(l, n) ? B_CONT : B_PARA;
        }
        l = next;
    }
    if (cur && push(v, cur, strlen(cur), fence ? B_FENCE : kind, 0, after))
        return -1;
    return 0;
}

static int labelled(const block *b, const char *label)
{
    size_t k = strlen(label);
    return b->kind == B_PARA && b->n > 2 + k && !strncmp(b->s, "**", 2) && !strncmp(b->s + 2, label, k);
}

static int heading_is_history(const block *b)
{
    const char *t = b->s + b->level;
    while (*t == ' ')
        t++;
    return !strncasecmp(t, "History", 7);
}

static void assign(blocks *v)
{
    int hist = 0, have[D_DROP + 1] = { 0 }, prev = D_REST;
    for (size_t i = 0; i < v->n; i++) {
        block *b = &v->b[i];
        if (i && b->after != v->b[i - 1].after)
            hist = 0;   /* the scene block ends a history section */
        if (b->kind == B_HEAD) {
            if (hist && b->level <= hist)
                hist = 0;
            if (!hist && heading_is_history(b)) {
                hist = b->level;
                b->dest = prev = D_DROP;
                continue;
            }
        }
        int d = D_REST;
        if (hist)
            d = D_HIST;
        else if (b->kind == B_CONT && prev != D_REST && prev != D_DROP)
            d = prev;
        else if (labelled(b, "History"))
            d = D_HIST;
        else if (labelled(b, "Claim") && !have[D_CLAIM])
            d = D_CLAIM;
        else if (labelled(b, "Why") && !have[D_WHY])
            d = D_WHY;
        else if ((labelled(b, "Test") || labelled(b, "The test") || labelled(b, "How")) && !have[D_TEST])
            d = D_TEST;
        else if (labelled(b, "Tolerance") && !have[D_TOL])
            d = D_TOL;
        have[d] = 1;
        b->dest = prev = d;
    }
    if (!have[D_CLAIM])   /* the first paragraph is the claim */
        for (size_t i = 0; i < v->n; i++)
            if (v->b[i].dest == D_REST && v->b[i].kind == B_PARA) {
                v->b[i].dest = D_CLAIM;
                break;
            }
}

/* the blocks bound for dest (on side `after`, or either when -1), joined
 * by blank lines; NULL when out of memory */
static char *join(const blocks *v, int dest, int after, int *found)
{
    char *s = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&s, &n);
    if (!f)
        return NULL;
    int any = 0;
    for (size_t i = 0; i < v->n; i++) {
        const block *b = &v->b[i];
        if (b->dest != dest || (after >= 0 && b->after != after))
            continue;
        fprintf(f, "%s%.*s\n", any ? "\n" : "", (int)b->n, b->s);
        any = 1;
    }
    if (fclose(f) != 0) {
        free(s);
        return NULL;
    }
    if (found)
        *found = any;
    return s;
}

void sf_prose_free(sf_prose *p)
{
    char *parts[] = { p->claim, p->why, p->test, p->tolerance, p->rest_before, p->rest_after, p->history };
    for (size_t i = 0; i < sizeof parts / sizeof *parts; i++)
        free(parts[i]);
    memset(p, 0, sizeof *p);
}

int sf_prose_split(sf_prose *p, const char *before, const char *after)
{
    memset(p, 0, sizeof *p);
    blocks v = { 0 };
    if (split_blocks(&v, before, 0) || split_blocks(&v, after, 1)) {
        free(v.b);
        return -1;
    }
    assign(&v);
    for (size_t i = 0; i < v.n; i++)
        if (v.b[i].dest == D_CLAIM)
            p->claim_labelled = labelled(&v.b[i], "Claim");
    int fw = 0, ft = 0, fo = 0, ok = 1;
    p->claim = join(&v, D_CLAIM, -1, NULL);
    p->why = join(&v, D_WHY, -1, &fw);
    p->test = join(&v, D_TEST, -1, &ft);
    p->tolerance = join(&v, D_TOL, -1, &fo);
    p->rest_before = join(&v, D_REST, 0, NULL);
    p->rest_after = join(&v, D_REST, 1, NULL);
    p->history = join(&v, D_HIST, -1, NULL);
    free(v.b);
    ok = p->claim && p->why && p->test && p->tolerance && p->rest_before && p->rest_after && p->history;
    if (!ok) {
        sf_prose_free(p);
        return -1;
    }
    if (!fw) { free(p->why); p->why = NULL; }
    if (!ft) { free(p->test); p->test = NULL; }
    if (!fo) { free(p->tolerance); p->tolerance = NULL; }
    return 0;
}
