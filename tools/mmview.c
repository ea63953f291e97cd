/* mmview - replay an LCM log of a run (mmsim --lcm-log) in the 3D viewer:
 * the same scene and HUD as mmsim --gui, driven by the log (sim/view/replay.h),
 * with a time slider; or one frame of it to a PNG file.
 *
 *   mmview LOG [--speed 1..64] [--camera 1|2|3] [--size WxH]
 *   mmview LOG --screenshot FILE.png --at SECONDS [--camera N] [--size WxH]
 *
 * The log alone is enough: its MM_MAZE message carries the maze, the
 * config, the robot and the seed, from which the run's model is built;
 * no physics runs. Exit codes: 0 ok, 2 bad input (flags, a missing,
 * corrupt or truncated log), 3 external failure (no display, no OpenGL). */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "io/outfile.h"
#include "io/stdstream.h"
#include "view/replay.h"
#include "view/view.h"

enum { EXIT_OK = 0, EXIT_BAD_INPUT = 2, EXIT_EXTERNAL = 3 };

static void usage(FILE *out)
{
    fputs("usage: mmview LOG [--speed 1..64] [--camera 1|2|3] [--size WxH]\n"
          "       mmview LOG --screenshot FILE.png --at SECONDS [--camera 1|2|3] [--size WxH]\n"
          "Replays a log of mmsim --lcm-log in the 3D viewer: time slider (click or drag), space play/pause,\n"
          "S / , one pose forward / back, + / - speed, Left / Right one second, 1/2/3 cameras, O overlay.\n"
          "Exit codes: 0 ok, 2 bad input, 3 external failure (no display).\n",
          out);
}

typedef struct {
    view_opts_t view;
    const char *shot; /* --screenshot FILE.png */
    double at_s;      /* --at, s of the log; -1 none */
    int help;
} mmview_opts_t;

static int bad(const char *fmt, const char *arg) { return cli_bad("mmview", fmt, arg); }
static view_opts_t *view_of(void *o) { return &((mmview_opts_t *)o)->view; }
static int f_camera(const char *prog, void *o, const char *arg) { return cli_view_option(prog, "camera", arg, view_of(o)); }
static int f_speed(const char *prog, void *o, const char *arg) { return cli_view_option(prog, "speed", arg, view_of(o)); }
static int f_size(const char *prog, void *o, const char *arg) { return cli_view_option(prog, "size", arg, view_of(o)); }

static const cli_opt_t flags[] = {
    { .name = "screenshot", .kind = CLI_STR, .off = offsetof(mmview_opts_t, shot) },
    { .name = "at", .kind = CLI_NUM, .off = offsetof(mmview_opts_t, at_s), .lo = 0, .hi = 86400 },
    { .name = "camera", .kind = CLI_FN, .fn = f_camera, .has_arg = 1 },
    { .name = "size", .kind = CLI_FN, .fn = f_size, .has_arg = 1 },
    { .name = "speed", .kind = CLI_FN, .fn = f_speed, .has_arg = 1 },
    { .name = "help", .kind = CLI_SET, .off = offsetof(mmview_opts_t, help) },
    { NULL },
};

/* The flags and the one operand: 0, or EXIT_BAD_INPUT after one error line. */
static int parse(int argc, char **argv, mmview_opts_t *m, const char **log)
{
    int first;
    if (cli_parse("mmview", flags, argc, argv, m, NULL, &first)) return EXIT_BAD_INPUT;
    if (m->help) return 0;
    if (first >= argc) return bad("%s", "LOG is required");
    if (first + 1 < argc) return bad("unexpected argument '%s'", argv[first + 1]);
    *log = argv[first];
    if (m->at_s >= 0 && !m->shot) return bad("%s", "--at needs --screenshot FILE.png");
    if (m->shot && m->at_s < 0) return bad("%s", "--screenshot needs --at SECONDS");
    if (m->shot) { /* fail now, before loading the log */
        char perr[600];
        if (outfile_probe(m->shot, perr, sizeof perr) != 0) {
            fprintf(stderr, "mmview: --screenshot: %s\n", perr);
            return EXIT_BAD_INPUT;
        }
    }
    return 0;
}

/* The viewer on the replayed log: played, or one frame to a file. */
static int show(const mmview_opts_t *m, replay_t *rp)
{
    char err[600];
    int rc = EXIT_OK;
    view_t *v = view_new(&m->view);
    snprintf(err, sizeof err, "out of memory");
    if (!v || view_open(v, m->shot == NULL, err, sizeof err) != 0) {
        fprintf(stderr, "mmview: %s\n", err);
        rc = EXIT_EXTERNAL;
    } else {
        view_set_replay(v, rp);
        if (m->shot) {
            view_seek(v, m->at_s);
            if (view_screenshot(v, NULL, m->shot, err, sizeof err) != 0) {
                fprintf(stderr, "mmview: %s\n", err);
                rc = EXIT_EXTERNAL;
            }
        } else {
            view_play(v);
        }
    }
    view_free(v);
    return rc;
}

static int run(int argc, char **argv)
{
    mmview_opts_t m = { .view = { 1024, 720, 1, 1, "", 115200 }, .at_s = -1 };
    const char *log = NULL;
    if (parse(argc, argv, &m, &log)) return EXIT_BAD_INPUT;
    if (m.help) {
        usage(stdout);
        return EXIT_OK;
    }
    static replay_t rp;
    char err[4200];
    if (replay_load(&rp, log, err, sizeof err) != 0) {
        fprintf(stderr, "mmview: %s\n", err);
        replay_free(&rp);
        return EXIT_BAD_INPUT;
    }
    if (m.shot && m.at_s > replay_end_s(&rp) + 1e-9) {
        fprintf(stderr, "mmview: --at %g: the log ends at %.3f s\n", m.at_s, replay_end_s(&rp));
        replay_free(&rp);
        return EXIT_BAD_INPUT;
    }
    int rc = show(&m, &rp);
    replay_free(&rp);
    return rc;
}

int main(int argc, char **argv)
{
    io_stdout_open("mmview");
    int rc = run(argc, argv);
    return io_stdout_close("mmview") != 0 ? EXIT_EXTERNAL : rc;
}
