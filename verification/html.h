/* slipfield verification: HTML pages rendered from the reports' Markdown
 * with cmark-gfm (CommonMark + GFM tables).  Raw HTML in case prose is not
 * passed through (cmark's safe default).  One small inline script marks
 * broken images for the browser test; no framework, no network. */
#ifndef SF_HTML_H
#define SF_HTML_H

#include <stddef.h>

/* Render markdown to a standalone page at path (temporary name + rename).
 * Returns 0, or -1 with a message in err. */
int sf_html_write(const char *path, const char *title, const char *markdown,
                  char *err, size_t errlen);

#endif
