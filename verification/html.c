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

/* Colour the verdict words the Markdown writers emphasise. */
static void write_body(FILE *f, const char *html)
{
    static const char *from[] = { "<strong>PASS</strong>", "<strong>FAIL</strong>", "<strong>ERROR</strong>" };
    static const char *to[] = { "<strong class=\"pass\">PASS</strong>", "<strong class=\"fail\">FAIL</strong>",
                                "<strong class=\"error\">ERROR</strong>" };
    const char *p = html;
    while (*p) {
        int hit = -1;
        for (int k = 0; k < 3; k++)
            if (!strncmp(p, from[k], strlen(from[k]))) { hit = k; break; }
        if (hit >= 0) {
            fputs(to[hit], f);
            p += strlen(from[hit]);
        } else {
            fputc(*p++, f);
        }
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
    /* Broken-image marker read by the browser test (tests/browser). */
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
