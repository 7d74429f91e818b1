/*
 * cli_options.c - parse long options and print their usage and help, all
 * from one table (see cli_options.h for the rules). Plain C99.
 */
#include "cli_options.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define HELP_WIDTH 79  /* lines are wrapped to this many columns */
#define HELP_COLUMN 25 /* where an option's description starts */

static const char *const count_words[] = { "none", "one", "two", "three", "four" };

/* Word wrapping: append an unbreakable item, starting a new line when full. */
struct wrap {
    FILE *f;
    int col;    /* the current column */
    int indent; /* where continuation lines start */
};

static void wrap_put(struct wrap *w, const char *item, int len)
{
    if (w->col > w->indent) {
        if (w->col + 1 + len > HELP_WIDTH) {
            fprintf(w->f, "\n%*s", w->indent, "");
            w->col = w->indent;
        } else {
            fputc(' ', w->f);
            w->col++;
        }
    }
    fprintf(w->f, "%.*s", len, item);
    w->col += len;
}

static void wrap_words(struct wrap *w, const char *text)
{
    while (*text != '\0') {
        int len = (int)strcspn(text, " ");
        if (len > 0)
            wrap_put(w, text, len);
        text += len;
        text += strspn(text, " ");
    }
}

/* "--name VALUES"; for the usage, in brackets unless required, "..." if repeatable. */
static int synopsis(char *buf, size_t size, const struct cli_option *opt, int usage)
{
    int optional = usage && !(opt->flags & CLI_REQUIRED);
    int len = snprintf(buf, size, "%s%s%s%s%s%s", optional ? "[" : "", opt->name,
                       opt->metavar != NULL ? " " : "",
                       opt->metavar != NULL ? opt->metavar : "", optional ? "]" : "",
                       usage && (opt->flags & CLI_REPEAT) ? "..." : "");
    return len < (int)size ? len : (int)size - 1;
}

/* "(--a A | --b B)": the CLI_ONE_OF group, whose first member is options[first]. */
static int group_synopsis(char *buf, size_t size, const struct cli_table *t, size_t first)
{
    size_t k, len = 1;

    buf[0] = '(';
    for (k = first; k < t->count && (t->options[k].flags & CLI_ONE_OF); k++) {
        if (k > first && len + 3 < size)
            len += (size_t)snprintf(buf + len, size - len, " | ");
        if (len < size)
            len += (size_t)synopsis(buf + len, size - len, &t->options[k], 0);
    }
    if (len + 1 < size)
        buf[len++] = ')';
    buf[len < size ? len : size - 1] = '\0';
    return (int)strlen(buf);
}

/* The CLI_ONE_OF names joined with sep, the last with last: "--a, --b or --c". */
static void group_names(char *buf, size_t size, const struct cli_table *t, const char *sep,
                        const char *last)
{
    size_t k, len = 0, left = 0;

    buf[0] = '\0';
    for (k = 0; k < t->count; k++)
        left += (t->options[k].flags & CLI_ONE_OF) != 0;
    for (k = 0; k < t->count; k++)
        if ((t->options[k].flags & CLI_ONE_OF) && len < size) {
            left--;
            len += (size_t)snprintf(buf + len, size - len, "%s%s",
                                    len == 0 ? "" : left == 0 ? last : sep, t->options[k].name);
        }
}

void cli_print_usage(const struct cli_table *t, FILE *f)
{
    struct wrap w;
    const char *sep = "";
    char item[80];
    size_t k;
    int group_done = 0;

    w.f = f;
    w.indent = w.col = fprintf(f, "usage: %s ", t->prog);
    for (k = 0; k < t->count; k++) {
        if (t->options[k].flags & CLI_ALONE)
            continue;
        if (!(t->options[k].flags & CLI_ONE_OF))
            wrap_put(&w, item, synopsis(item, sizeof item, &t->options[k], 1));
        else if (!group_done++)
            wrap_put(&w, item, group_synopsis(item, sizeof item, t, k));
    }
    fprintf(f, "\n       %s ", t->prog);
    for (k = 0; k < t->count; k++)
        if (t->options[k].flags & CLI_ALONE) {
            fprintf(f, "%s%s", sep, t->options[k].name);
            sep = " | ";
        }
    fputc('\n', f);
}

void cli_print_help(const struct cli_table *t, FILE *f)
{
    char item[80];
    size_t k;

    cli_print_usage(t, f);
    fprintf(f, "\n%s\n", t->intro);
    for (k = 0; k < t->count; k++) {
        const struct cli_option *opt = &t->options[k];
        struct wrap w;
        int len = synopsis(item, sizeof item, opt, 0);

        fprintf(f, "  %s", item);
        if (2 + len + 1 > HELP_COLUMN) /* too long: the text starts on the next line */
            fprintf(f, "\n%*s", HELP_COLUMN, "");
        else
            fprintf(f, "%*s", HELP_COLUMN - 2 - len, "");
        w.f = f;
        w.col = w.indent = HELP_COLUMN;
        wrap_words(&w, opt->help);
        if (opt->flags & CLI_REQUIRED)
            wrap_words(&w, "(required)");
        if (opt->flags & CLI_ONE_OF) {
            char names[80], text[120];
            group_names(names, sizeof names, t, ", ", ", ");
            snprintf(text, sizeof text, "(required: exactly one of %s)", names);
            wrap_words(&w, text);
        }
        if (opt->defval != NULL) {
            char text[80];
            snprintf(text, sizeof text, "(default %s)", opt->defval);
            wrap_words(&w, text);
        }
        fputc('\n', f);
    }
    fprintf(f, "\n%s", t->outro);
}

int cli_usage_error(const struct cli_table *t, const char *fmt, ...)
{
    va_list ap;

    fprintf(stderr, "%s: ", t->prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    cli_print_usage(t, stderr);
    fprintf(stderr, "Try '%s --help' for more information.\n", t->prog);
    return CLI_EXIT_USAGE;
}

/* Call the handler; on a bad value, say which and what it must be. */
static int handle(const struct cli_table *t, const struct cli_option *opt,
                  const char *const *values, void *ctx)
{
    int rc = opt->handle(ctx, opt, values);
    int bad = CLI_BAD(0) - rc;

    if (rc >= CLI_STOP)
        return rc;
    if (bad >= opt->nvalues) /* a handler outside its contract */
        return cli_usage_error(t, "%s: invalid value", opt->name);
    return cli_usage_error(t, "%s: expected %s, got '%s'", opt->name, opt->expect,
                           values[bad]);
}

/* Each default, split at blanks, goes through the option's own handler. */
static int apply_defaults(const struct cli_table *t, void *ctx)
{
    size_t k;

    for (k = 0; k < t->count; k++) {
        const struct cli_option *opt = &t->options[k];
        const char *values[CLI_MAX_VALUES];
        char text[80];
        char *p = text;
        int n, rc;

        if (opt->defval == NULL)
            continue;
        snprintf(text, sizeof text, "%s", opt->defval);
        for (n = 0; n < CLI_MAX_VALUES && *p != '\0'; n++) {
            values[n] = p;
            p += strcspn(p, " ");
            if (*p != '\0')
                *p++ = '\0';
        }
        if (n != opt->nvalues)
            return cli_usage_error(t, "%s: the default '%s' has %s values, not %s", opt->name,
                                   opt->defval, count_words[n], count_words[opt->nvalues]);
        if ((rc = handle(t, opt, values, ctx)) != CLI_OK)
            return rc;
    }
    return CLI_OK;
}

int cli_parse_double(const char *text, double *out)
{
    char *end;
    double v;

    /* strtod() alone would accept leading blanks, trailing junk, "nan", "inf". */
    if (text[0] == '\0' || text[0] == ' ' || (text[0] >= '\t' && text[0] <= '\r'))
        return -1;
    v = strtod(text, &end);
    /* Overflow gives +-HUGE_VAL (not finite); underflow is harmless here. */
    if (*end != '\0' || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

int cli_parse_u64(const char *text, uint64_t *out)
{
    char *end;
    unsigned long long v;

    /* strtoull() would silently negate "-5" and skip blanks: allow digits only. */
    if (text[0] < '0' || text[0] > '9')
        return -1;
    errno = 0;
    v = strtoull(text, &end, 10);
    /* The last test matters only where unsigned long long is wider than 64 bits. */
    if (*end != '\0' || errno == ERANGE || v > (unsigned long long)UINT64_MAX)
        return -1;
    *out = (uint64_t)v;
    return 0;
}

int cli_parse(const struct cli_table *t, int argc, char **argv, void *ctx)
{
    int i, rc;
    size_t k;
    unsigned char seen[64] = { 0 }; /* per option: given on the command line */
    const struct cli_option *chosen = NULL; /* the CLI_ONE_OF member given */
    int has_group = 0;

    if (t->count > sizeof seen)
        return cli_usage_error(t, "too many options in the table");
    if ((rc = apply_defaults(t, ctx)) != CLI_OK)
        return rc;
    for (i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *eq = strchr(arg, '=');
        size_t namelen = eq != NULL ? (size_t)(eq - arg) : strlen(arg);
        const struct cli_option *opt = NULL;
        const char *values[CLI_MAX_VALUES];
        int n;

        if (arg[0] != '-')
            return cli_usage_error(t, "unexpected argument '%s'", arg);
        for (k = 0; k < t->count && opt == NULL; k++)
            if (strlen(t->options[k].name) == namelen
                && strncmp(t->options[k].name, arg, namelen) == 0)
                opt = &t->options[k];
        if (opt == NULL)
            return cli_usage_error(t, "unknown option '%s'", arg);
        if (opt->nvalues == 0 && eq != NULL)
            return cli_usage_error(t, "option %s takes no value, got '%s'", opt->name, eq + 1);

        for (n = 0; n < opt->nvalues; n++) {
            if (n == 0 && eq != NULL) {
                values[n] = eq + 1;
                continue;
            }
            if (i + 1 >= argc || (opt->nvalues > 1 && strncmp(argv[i + 1], "--", 2) == 0)) {
                if (opt->nvalues == 1)
                    return cli_usage_error(t, "option %s needs a value", opt->name);
                return cli_usage_error(t, "%s needs %s values %s, got %s", opt->name,
                                       count_words[opt->nvalues], opt->metavar,
                                       count_words[n]);
            }
            values[n] = argv[++i];
        }
        if (opt->flags & CLI_ONE_OF) {
            if (chosen != NULL && chosen != opt)
                return cli_usage_error(t, "%s cannot be used with %s", opt->name, chosen->name);
            chosen = opt;
        }
        seen[opt - t->options] = 1;
        if ((rc = handle(t, opt, values, ctx)) != CLI_OK)
            return rc;
    }
    for (k = 0; k < t->count; k++) {
        if ((t->options[k].flags & CLI_REQUIRED) && !seen[k])
            return cli_usage_error(t, "option %s is required", t->options[k].name);
        has_group |= (t->options[k].flags & CLI_ONE_OF) != 0;
    }
    if (has_group && chosen == NULL) {
        char names[80];
        group_names(names, sizeof names, t, ", ", " or ");
        return cli_usage_error(t, "one of %s is required", names);
    }
    return CLI_OK;
}
