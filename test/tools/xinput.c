/* xinput.c - types and clicks into an X display through the XTEST
 * extension, for the viewer's CLI tests (test/cli/cli_connect.sh; libxtst-dev).
 *
 *   xinput wait NAME SECONDS       wait until a top-level window is named NAME
 *   xinput click X Y               left click at root (X, Y)
 *   xinput type TEXT               type TEXT (unshifted US keys: a-z 0-9 / . - _)
 *   xinput key KEYSYM              press and release one key (Return, Escape)
 * Exit 0 done, 1 not found / failed, 2 usage. */
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void nap_ms(long ms)
{
    struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };
    nanosleep(&ts, NULL);
}

static int named(Display *d, const char *name)
{
    Window root, parent, *kids = NULL;
    unsigned n = 0;
    int found = 0;
    if (!XQueryTree(d, DefaultRootWindow(d), &root, &parent, &kids, &n)) return 0;
    for (unsigned i = 0; i < n && !found; i++) {
        char *s = NULL;
        XWindowAttributes a;
        if (XFetchName(d, kids[i], &s) && s) {
            found = !strcmp(s, name) && XGetWindowAttributes(d, kids[i], &a) && a.map_state == IsViewable;
            XFree(s);
        }
    }
    if (kids) XFree(kids);
    return found;
}

static int key(Display *d, KeySym ks, int shift)
{
    KeyCode kc = XKeysymToKeycode(d, ks), sc = XKeysymToKeycode(d, XK_Shift_L);
    if (!kc) return -1;
    if (shift) XTestFakeKeyEvent(d, sc, True, 0);
    XTestFakeKeyEvent(d, kc, True, 0);
    XTestFakeKeyEvent(d, kc, False, 0);
    if (shift) XTestFakeKeyEvent(d, sc, False, 0);
    XFlush(d);
    nap_ms(20);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) return 2;
    Display *d = XOpenDisplay(NULL);
    if (!d) {
        fprintf(stderr, "xinput: cannot open the display\n");
        return 1;
    }
    int rc = 0;
    if (!strcmp(argv[1], "wait") && argc == 4) {
        double left_ms = atof(argv[3]) * 1000;
        while (!named(d, argv[2]) && left_ms > 0) {
            nap_ms(50);
            left_ms -= 50;
        }
        rc = left_ms > 0 ? 0 : 1;
    } else if (!strcmp(argv[1], "click") && argc == 4) {
        XTestFakeMotionEvent(d, -1, atoi(argv[2]), atoi(argv[3]), 0);
        XFlush(d);
        nap_ms(50);
        XTestFakeButtonEvent(d, 1, True, 0);
        XTestFakeButtonEvent(d, 1, False, 0);
        XFlush(d);
    } else if (!strcmp(argv[1], "type")) {
        for (const char *c = argv[2]; *c && rc == 0; c++) {
            KeySym ks = *c == '/' ? XK_slash : *c == '.' ? XK_period : *c == '-' ? XK_minus : (KeySym)(unsigned char)*c;
            int shift = *c == '_';
            if (*c == '_') ks = XK_minus;
            if (key(d, ks, shift) != 0) rc = 1;
        }
    } else if (!strcmp(argv[1], "key")) {
        KeySym ks = XStringToKeysym(argv[2]);
        rc = ks == NoSymbol || key(d, ks, 0) != 0;
    } else {
        rc = 2;
    }
    nap_ms(50);
    XCloseDisplay(d);
    return rc;
}
