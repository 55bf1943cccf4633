/* slipfield verification: a case's prose in the parts its report shows.
 *
 * A report opens with the claim, why it should hold, the test and the
 * result; the rest of the prose follows the evidence, and the history
 * (earlier designs, seed lists, fresh-seed studies) closes it.  The parts
 * are read from the case's paragraphs (blocks between blank lines; a
 * fenced block is one block) by their bold labels (cases/README.md):
 *
 *   claim      the first paragraph labelled **Claim...**; without one,
 *              the first paragraph that is not a heading (claim_labelled 0)
 *   why        the first labelled **Why...** (none: NULL)
 *   test       the first labelled **Test...**, **The test...** or **How...**
 *   tolerance  the first labelled **Tolerance...**
 *   history    every block under a heading `## History...` (any level, up
 *              to the next heading of the same or a higher level; the
 *              heading itself is dropped) and every paragraph labelled
 *              **History...**, in order
 *   rest_*     every other block, in order: before and after the scene
 *
 * A list or an indented block that follows a paragraph taken for a part
 * (with a blank line between) goes with it.  Every string is "" when
 * empty, never NULL, except why/test/tolerance (NULL: the case has none). */
#ifndef SF_PROSE_H
#define SF_PROSE_H

typedef struct {
    char *claim, *why, *test, *tolerance;
    char *rest_before, *rest_after, *history;
    int claim_labelled;
} sf_prose;

/* Split a case's prose (before and after its scene block; either may be
 * NULL).  0, or -1 when out of memory (p then holds nothing to free). */
int sf_prose_split(sf_prose *p, const char *before, const char *after);
void sf_prose_free(sf_prose *p);

#endif
