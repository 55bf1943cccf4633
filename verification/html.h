/* slipfield verification: HTML pages rendered from the reports' Markdown
 * with cmark-gfm (CommonMark + GFM tables).  Raw HTML in case prose is not
 * passed through (cmark's safe default).  One small inline script marks
 * broken images for the browser test; no framework, no network. */
#ifndef SF_HTML_H
#define SF_HTML_H

#include <stddef.h>
#include <stdio.h>

/* Render markdown to a standalone page at path (temporary name + rename).
 * Returns 0, or -1 with a message in err. */
int sf_html_write(const char *path, const char *title, const char *markdown,
                  char *err, size_t errlen);

/* Write generated text (a row's quantity, a claim, a key metric) into
 * Markdown as literal text: no emphasis, link, code span, entity or raw
 * HTML from its characters (a path with a star stays a path), '|'
 * escaped for table cells, line breaks and tabs as spaces.  Only what
 * could change the rendering is escaped, so the .md stays readable: an
 * underscore inside a word (PV_x) cannot open emphasis, "<=" is no tag,
 * a unit in brackets ([N m]) is no link. */
void sf_md_text(FILE *f, const char *s);

#endif
