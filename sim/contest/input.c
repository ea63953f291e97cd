/* input.c - the scripted person's hands (see input.h). */
#include "input.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/escape.h"
#include "io/number.h"

/* "COL: reason" (COL counted from 1); input_add puts "--input:N:" before it. */
static int fail(char *err, size_t errlen, size_t col, const char *what, const char *word)
{
    char w[IO_ESCAPE_MAX(100)]; /* the user's text: a newline in it must not end our line */
    if (word) io_escape(w, sizeof w, word, strnlen(word, 100));
    if (snprintf(err, errlen, "%zu: %s%s%s", col + 1, what, word ? ": " : "", word ? w : "") < 0) err[0] = '\0';
    return -1;
}

static int add(input_t *in, double t, input_kind_t k, int v, const char *text, char *err, size_t errlen, size_t col)
{
    if (in->n == INPUT_MAX) return fail(err, errlen, col, "more than 64 actions", NULL);
    input_action_t *a = &in->a[in->n++];
    a->t_s = t;
    a->kind = k;
    a->value = v;
    memset(a->push, 0, sizeof a->push);
    a->spec = in->specs;
    a->col = (int)col + 1;
    snprintf(a->text, sizeof a->text, "%.79s", text ? text : "");
    return 0;
}

/* One number of push's list at p (up to ',' or the end) into v: 0 or -1. */
static int push_number(const char **p, double *v)
{
    size_t n = strcspn(*p, ",");
    if (io_decimal(*p, n, v) != 0) return -1;
    *p += (*p)[n] ? n + 1 : n;
    return 0;
}

/* "push=DX_MM[,DYAW_DEG[,SECONDS]]" (args: after the '='). */
static int push(input_t *in, double t, const char *args, char *err, size_t errlen, size_t col)
{
    double v[3] = { 0, 0, INPUT_PUSH_S };
    const char *p = args;
    for (int i = 0; i < 3 && *p; i++)
        if (push_number(&p, &v[i]) != 0) return fail(err, errlen, col, "push=DX_MM[,DYAW_DEG[,SECONDS]] wants numbers", args);
    if (p == args || *p) return fail(err, errlen, col, "push=DX_MM[,DYAW_DEG[,SECONDS]] wants 1 to 3 numbers", args);
    if (fabs(v[0]) > INPUT_PUSH_MAX_MM || fabs(v[1]) > INPUT_PUSH_MAX_DEG)
        return fail(err, errlen, col, "push: DX_MM within +-5000 mm and DYAW_DEG within +-3600 deg", args);
    if (v[2] < INPUT_PUSH_MIN_S || v[2] > INPUT_PUSH_MAX_S) return fail(err, errlen, col, "push: SECONDS within 0.05..60 s", args);
    if (2 * fabs(v[0]) / 1000 / v[2] > INPUT_PUSH_MAX_M_S || 2 * fabs(v[1]) / v[2] > INPUT_PUSH_MAX_DEG_S)
        return fail(err, errlen, col, "push: faster than a hand (peak 2*DX/SECONDS <= 1 m/s, 2*DYAW/SECONDS <= 1440 deg/s)", args);
    if (add(in, t, INPUT_PUSH, 0, NULL, err, errlen, col) != 0) return -1;
    memcpy(in->a[in->n - 1].push, v, sizeof v);
    return 0;
}

/* One "ACTION" (its text in w, n bytes) at time t. */
static int action(input_t *in, double t, const char *w, size_t n, char *err, size_t errlen, size_t col)
{
    char word[INPUT_TEXT_MAX + 8];
    if (n >= sizeof word) return fail(err, errlen, col, "action too long", NULL);
    memcpy(word, w, n);
    word[n] = '\0';
    if (!strncmp(word, "send=", 5)) {
        if (n - 5 >= INPUT_TEXT_MAX) return fail(err, errlen, col, "send text longer than 79 bytes", NULL);
        return add(in, t, INPUT_SEND, 0, word + 5, err, errlen, col);
    }
    if (!strncmp(word, "switches=", 9)) {
        double v;
        if (io_decimal(word + 9, strlen(word + 9), &v) != 0 || v != floor(v) || v < 0 || v > 15)
            return fail(err, errlen, col, "switches=N wants N in 0..15", word);
        return add(in, t, INPUT_SWITCHES, (int)v, NULL, err, errlen, col);
    }
    if (!strcmp(word, "button"))
        return add(in, t, INPUT_BUTTON_DOWN, 0, NULL, err, errlen, col) ||
               add(in, t + INPUT_BUTTON_S, INPUT_BUTTON_UP, 0, NULL, err, errlen, col);
    if (!strcmp(word, "button=down")) return add(in, t, INPUT_BUTTON_DOWN, 0, NULL, err, errlen, col);
    if (!strcmp(word, "button=up")) return add(in, t, INPUT_BUTTON_UP, 0, NULL, err, errlen, col);
    if (!strncmp(word, "button=", 7)) { /* a press held SECONDS: a short or a long one to a firmware that tells them apart */
        double s;
        if (io_decimal(word + 7, strlen(word + 7), &s) != 0 || s < INPUT_PRESS_MIN_S || s > INPUT_PRESS_MAX_S)
            return fail(err, errlen, col, "button=SECONDS wants 0.01 to 60 seconds (or down, up)", word);
        return add(in, t, INPUT_BUTTON_DOWN, 0, NULL, err, errlen, col) || add(in, t + s, INPUT_BUTTON_UP, 0, NULL, err, errlen, col);
    }
    if (!strcmp(word, "reset")) return add(in, t, INPUT_RESET, 0, NULL, err, errlen, col);
    if (!strncmp(word, "occlude=", 8)) {
        if (!word[8] || n - 8 >= INPUT_NAME_MAX) return fail(err, errlen, col, "occlude=NAME wants a sensor's name from the robot file", word);
        return add(in, t, INPUT_OCCLUDE, -1, word + 8, err, errlen, col);
    }
    if (!strcmp(word, "end")) return add(in, t, INPUT_END, 0, NULL, err, errlen, col);
    if (!strncmp(word, "push=", 5)) return push(in, t, word + 5, err, errlen, col);
    if (!strcmp(word, "lift")) return add(in, t, INPUT_LIFT, 0, NULL, err, errlen, col);
    if (!strcmp(word, "place")) return add(in, t, INPUT_PLACE, 0, NULL, err, errlen, col);
    return fail(err, errlen, col,
                "unknown action (switches=N, button, button=SECONDS, button=down, button=up, reset, occlude=NAME, push=DX_MM[,DYAW_DEG[,SECONDS]], lift, place, send=TEXT, end)",
                word);
}

int input_parse(input_t *in, const char *spec, char *err, size_t errlen)
{
    memset(in, 0, sizeof *in);
    return input_add(in, spec, err, errlen);
}

/* Sort in->a by time; equal times keep the order they were added in. */
static void sort_by_time(input_t *in)
{
    input_action_t tmp[INPUT_MAX];
    int idx[INPUT_MAX];
    for (int i = 0; i < in->n; i++) idx[i] = i;
    for (int i = 1; i < in->n; i++) /* insertion sort: stable, at most 64 */
        for (int j = i; j > 0 && in->a[idx[j - 1]].t_s > in->a[idx[j]].t_s; j--) {
            int t = idx[j];
            idx[j] = idx[j - 1];
            idx[j - 1] = t;
        }
    for (int i = 0; i < in->n; i++) tmp[i] = in->a[idx[i]];
    memcpy(in->a, tmp, sizeof(input_action_t) * (size_t)in->n);
}

/* Parse spec's actions onto the end of in->a: 0, or -1 with "COL: reason" in err. */
static int add_spec(input_t *in, const char *spec, char *err, size_t errlen)
{
    for (const char *p = spec; *p;) {
        while (*p == ' ' || *p == ';') p++;
        if (!*p) break;
        size_t col = (size_t)(p - spec);
        size_t tn = strcspn(p, " ;");
        double t;
        if (io_decimal(p, tn, &t) != 0 || t < 0 || t > 86400 || p[tn] != ' ')
            return fail(err, errlen, col, "want 'T ACTION' with T in simulation seconds (0..86400)", NULL);
        p += tn;
        while (*p == ' ') p++;
        const char *semi = strchr(p, ';');
        size_t n = semi ? (size_t)(semi - p) : strlen(p);
        while (n && p[n - 1] == ' ') n--;
        if (!n) return fail(err, errlen, (size_t)(p - spec), "missing action", NULL);
        if (action(in, t, p, n, err, errlen, (size_t)(p - spec)) != 0) return -1;
        p = semi ? semi + 1 : p + strlen(p);
    }
    return 0;
}

int input_add(input_t *in, const char *spec, char *err, size_t errlen)
{
    char why[300];
    in->specs++;
    if (add_spec(in, spec, why, sizeof why) != 0) {
        snprintf(err, errlen, "--input:%d:%s", in->specs, why);
        return -1;
    }
    sort_by_time(in);
    return 0;
}

const input_action_t *input_due(input_t *in, double t_s)
{
    if (in->next >= in->n || in->a[in->next].t_s > t_s + 1e-9) return NULL;
    return &in->a[in->next++];
}

int input_needs_board(const input_t *in)
{
    for (int i = 0; i < in->n; i++)
        switch (in->a[i].kind) {
        case INPUT_OCCLUDE: case INPUT_END: case INPUT_PUSH: case INPUT_LIFT: case INPUT_PLACE: break; /* on the world */
        default: return 1;
        }
    return 0;
}
