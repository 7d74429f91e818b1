/*
 * cli_progress.c - the progress line and the SIGINT flag (see cli_progress.h).
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_progress.h"

#include <signal.h>
#include <string.h>

/* Written by the handler, read between points: the only state shared with it. */
static volatile sig_atomic_t interrupted;

/* The disposition before cli_interrupt_begin(), put back by cli_interrupt_end(). */
static struct sigaction saved;
static int installed;

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

int cli_interrupt_begin(void)
{
    struct sigaction sa;

    if (sigaction(SIGINT, NULL, &saved) != 0)
        return -1;
    if (saved.sa_handler == SIG_IGN) /* the caller asked for Ctrl-C to be ignored */
        return 0;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    /* One-shot: a second Ctrl-C, while the first is being honoured, ends the program. */
    sa.sa_flags = SA_RESETHAND;
    if (sigaction(SIGINT, &sa, NULL) != 0)
        return -1;
    installed = 1;
    return 0;
}

void cli_interrupt_end(void)
{
    if (installed)
        sigaction(SIGINT, &saved, NULL);
    installed = 0;
}

int cli_interrupted(void)
{
    return interrupted != 0;
}

int cli_progress_report(void *user, size_t count, double done)
{
    struct cli_progress *p = user;
    char line[160];
    int len, pad;

    if (p->f != NULL) {
        len = snprintf(line, sizeof line, "%s: ", p->prog);
        if (p->nruns > 1 && len < (int)sizeof line)
            len += snprintf(line + len, sizeof line - (size_t)len, "stage %u/%u ", p->run,
                            p->nruns);
        if (len < (int)sizeof line)
            len += snprintf(line + len, sizeof line - (size_t)len, "%3d%% %zu", (int)(done * 100),
                            count);
        if (p->target > 0 && len < (int)sizeof line)
            len += snprintf(line + len, sizeof line - (size_t)len, "/%zu", p->target);
        if (len < (int)sizeof line)
            len += snprintf(line + len, sizeof line - (size_t)len, " points");
        if (len >= (int)sizeof line)
            len = (int)sizeof line - 1;
        /* Blanks over whatever is left of a longer line drawn before. */
        pad = p->width > len ? p->width - len : 0;
        fprintf(p->f, "\r%s%*s", line, pad, "");
        if (pad > 0)
            fprintf(p->f, "\r%s", line);
        fflush(p->f);
        p->width = len;
    }
    return interrupted != 0;
}

void cli_progress_clear(struct cli_progress *p)
{
    if (p->f != NULL && p->width > 0) {
        fprintf(p->f, "\r%*s\r", p->width, "");
        fflush(p->f);
    }
    p->width = 0;
}
