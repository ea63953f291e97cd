/* mmview - replay an LCM log of a run (mmsim --lcm-log) in the 3D viewer:
 * the same scene and HUD as mmsim --gui, driven by the log (sim/replay.h),
 * with a time slider; or one frame of it to a PNG file.
 *
 *   mmview LOG [--speed 1..64] [--camera 1|2|3] [--size WxH]
 *   mmview LOG --screenshot FILE.png --at SECONDS [--camera N] [--size WxH]
 *
 * The log alone is enough: its MM_MAZE message carries the maze, the
 * config and the seed. Exit codes: 0 ok, 2 bad input (flags, a missing,
 * corrupt or truncated log), 3 external failure (no display, no OpenGL). */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "io/outfile.h"
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

static int bad(const char *fmt, const char *arg) { return cli_bad("mmview", fmt, arg); }
static int num(const char *opt, const char *s, double lo, double hi, double *out)
{
    return cli_number("mmview", opt, s, lo, hi, out);
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        { "screenshot", required_argument, 0, 'S' }, { "at", required_argument, 0, 'A' },
        { "camera", required_argument, 0, 'C' },     { "size", required_argument, 0, 'Z' },
        { "speed", required_argument, 0, 'X' },      { "help", no_argument, 0, 'h' },
        { 0, 0, 0, 0 },
    };
    view_opts_t vo = { 1024, 720, 1, 1, "", 115200 };
    const char *shot = NULL;
    double at_s = -1;
    int c;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        switch (c) {
        case 'S': shot = optarg; break;
        case 'A':
            if (num("--at", optarg, 0, 86400, &at_s)) return EXIT_BAD_INPUT;
            break;
        case 'C':
            if (cli_view_option("mmview", "camera", optarg, &vo)) return EXIT_BAD_INPUT;
            break;
        case 'X':
            if (cli_view_option("mmview", "speed", optarg, &vo)) return EXIT_BAD_INPUT;
            break;
        case 'Z':
            if (cli_view_option("mmview", "size", optarg, &vo)) return EXIT_BAD_INPUT;
            break;
        case 'h': usage(stdout); return EXIT_OK;
        default: return bad("unknown option or missing value: '%s'", argv[optind - 1]);
        }
    }
    if (optind >= argc) return bad("%s", "LOG is required");
    if (optind + 1 < argc) return bad("unexpected argument '%s'", argv[optind + 1]);
    const char *log = argv[optind];
    if (at_s >= 0 && !shot) return bad("%s", "--at needs --screenshot FILE.png");
    if (shot && at_s < 0) return bad("%s", "--screenshot needs --at SECONDS");
    if (shot) { /* fail now, before loading the log */
        char perr[600];
        outfile_t probe;
        if (outfile_open(&probe, shot, perr, sizeof perr) != 0) {
            fprintf(stderr, "mmview: --screenshot: %s\n", perr);
            return EXIT_BAD_INPUT;
        }
        outfile_abort(&probe);
    }

    static replay_t rp;
    static sim_t sim;
    char err[4200];
    if (replay_load(&rp, log, err, sizeof err) != 0) {
        fprintf(stderr, "mmview: %s\n", err);
        replay_free(&rp);
        return EXIT_BAD_INPUT;
    }
    if (shot && at_s > replay_end_s(&rp) + 1e-9) {
        fprintf(stderr, "mmview: --at %g: the log ends at %.3f s\n", at_s, replay_end_s(&rp));
        replay_free(&rp);
        return EXIT_BAD_INPUT;
    }
    if (replay_sim_init(&rp, &sim) != 0) {
        fprintf(stderr, "mmview: %s: cannot set up the ODE world\n", log);
        replay_free(&rp);
        return EXIT_EXTERNAL;
    }
    int rc = EXIT_OK;
    view_t *v = view_new(&vo);
    snprintf(err, sizeof err, "out of memory");
    if (!v || view_open(v, shot == NULL, err, sizeof err) != 0) {
        fprintf(stderr, "mmview: %s\n", err);
        rc = EXIT_EXTERNAL;
    } else {
        view_set_replay(v, &rp, &sim);
        if (shot) {
            view_seek(v, at_s);
            if (view_screenshot(v, &sim, shot, err, sizeof err) != 0) {
                fprintf(stderr, "mmview: %s\n", err);
                rc = EXIT_EXTERNAL;
            }
        } else {
            view_play(v);
        }
    }
    view_free(v);
    sim_free(&sim);
    replay_free(&rp);
    return rc;
}
