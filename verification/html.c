/* The reports' HTML pages (html.h): Markdown rendered with cmark-gfm into
 * standalone pages with an inline style sheet and the broken-image marker. */
#include "html.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmark-gfm.h>
#include <cmark-gfm-core-extensions.h>

static const char *css =
    "body{font-family:'DejaVu Sans',Helvetica,Arial,sans-serif;max-width:1100px;margin:2em auto;"
    "padding:0 1em;color:#222;line-height:1.45}"
    "h1{font-size:1.6em;border-bottom:2px solid #1f77b4;padding-bottom:.2em}"
    "h2{font-size:1.25em;margin-top:1.6em;color:#1f4e79}"
    "table{border-collapse:collapse;margin:1em 0;font-size:.92em}"
    "th,td{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top}"
    "th{background:#eef3f8}tr:nth-child(even) td{background:#fafafa}"
    "code,pre{background:#f4f4f4;border-radius:3px}pre{padding:.6em;overflow-x:auto}"
    "img{max-width:100%;border:1px solid #ddd;margin:.5em 0}"
    ".pass{color:#1a7f37}.fail{color:#c62828}.error{color:#b26a00}";

/* Colour the verdict words the Markdown writers emphasise: a case's
 * PASS / FAIL / ERROR, a claim's confirmed / contradicted / not decidable
 * (the same three colours), optionally after a count ("**3 passed**"). */
static const struct { const char *word, *cls; } verdicts[] = {
    { "PASS", "pass" }, { "passed", "pass" }, { "confirmed", "pass" },
    { "FAIL", "fail" }, { "contradicted", "fail" }, { "contradicted in part", "fail" },
    { "ERROR", "error" }, { "not decidable", "error" }, { "not decidable at this N", "error" },
};

static const char *verdict_class(const char *inner, size_t len)
{
    while (len && ((*inner >= '0' && *inner <= '9') || *inner == ' ')) {
        inner++;
        len--;
    }
    for (size_t k = 0; k < sizeof verdicts / sizeof verdicts[0]; k++)
        if (strlen(verdicts[k].word) == len && !strncmp(inner, verdicts[k].word, len))
            return verdicts[k].cls;
    return NULL;
}

static void write_body(FILE *f, const char *html)
{
    static const char open[] = "<strong>", close[] = "</strong>";
    const char *p = html;
    while (*p) {
        const char *end = strncmp(p, open, sizeof open - 1) ? NULL : strstr(p, close);
        const char *cls = end ? verdict_class(p + sizeof open - 1, (size_t)(end - p) - (sizeof open - 1)) : NULL;
        if (cls) {
            fprintf(f, "<strong class=\"%s\">", cls);
            p += sizeof open - 1;
        } else {
            fputc(*p++, f);
        }
    }
}

static int word_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

void sf_md_text(FILE *f, const char *s)
{
    for (const char *p = s; *p; p++) {
        char c = *p, d = p[1];
        int special;
        if (c == '\n' || c == '\t' || c == '\r') {
            fputc(' ', f);
            continue;
        }
        if (c == '_')   /* intraword: cannot open or close emphasis */
            special = !(p > s && word_char(p[-1]) && word_char(d));
        else if (c == '<')   /* "<=" and "< 1" are text; "<a" could be a tag */
            special = word_char(d) || d == '/' || d == '!' || d == '?';
        else if (c == '&')   /* "&amp;" would be an entity */
            special = word_char(d) || d == '#';
        else if (c == ']')   /* "[N m]" is text; "[x](y)" and "[x][y]" are links */
            special = d == '(' || d == '[' || d == ':';
        else
            special = strchr("\\`*|", c) != NULL;
        if (special)
            fputc('\\', f);
        fputc(c, f);
    }
}

static void escape(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '<') fputs("&lt;", f);
        else if (*s == '>') fputs("&gt;", f);
        else if (*s == '&') fputs("&amp;", f);
        else if (*s == '"') fputs("&quot;", f);
        else fputc(*s, f);
    }
}

int sf_html_write(const char *path, const char *title, const char *markdown,
                  char *err, size_t errlen)
{
    cmark_gfm_core_extensions_ensure_registered();
    cmark_parser *parser = cmark_parser_new(CMARK_OPT_DEFAULT);
    cmark_syntax_extension *table = cmark_find_syntax_extension("table");
    if (!parser || !table) {
        snprintf(err, errlen, "cmark-gfm: cannot set up the parser");
        if (parser) cmark_parser_free(parser);
        return -1;
    }
    cmark_parser_attach_syntax_extension(parser, table);
    cmark_parser_feed(parser, markdown, strlen(markdown));
    cmark_node *doc = cmark_parser_finish(parser);
    char *html = cmark_render_html(doc, CMARK_OPT_DEFAULT, cmark_parser_get_syntax_extensions(parser));
    cmark_node_free(doc);
    cmark_parser_free(parser);
    if (!html) {
        snprintf(err, errlen, "cmark-gfm: rendering failed");
        return -1;
    }
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) {
        snprintf(err, errlen, "cannot write %s: %s", tmp, strerror(errno));
        free(html);
        return -1;
    }
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>", f);
    escape(f, title);
    fprintf(f, "</title>\n<style>%s</style>\n</head>\n<body>\n", css);
    write_body(f, html);
    /* Broken-image marker read by the browser test (scripts/report-test.sh). */
    fputs("<script>window.addEventListener('load',function(){var b=0;"
          "document.querySelectorAll('img').forEach(function(i){if(!i.complete||i.naturalWidth===0)b++;});"
          "document.body.setAttribute('data-broken-images',String(b));"
          "document.body.setAttribute('data-images',String(document.images.length));});</script>\n", f);
    fputs("</body>\n</html>\n", f);
    free(html);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad || rename(tmp, path) != 0) {
        unlink(tmp);
        snprintf(err, errlen, "cannot write %s", path);
        return -1;
    }
    return 0;
}
