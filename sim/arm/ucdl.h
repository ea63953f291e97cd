/* ucdl.h - libunicorn loaded only when an ARM core is made, not linked:
 * linking it costs every process ~32 M instructions of relocation at start
 * (docs/BENCHMARKS.md), runs without an ARM board included. ucdl.c defines
 * the uc_* functions the core calls (the declarations and constants stay
 * <unicorn/unicorn.h>'s) as calls through a table resolved by dlopen of
 * libunicorn.so.2 (Debian's libunicorn2, 2.0.1), or the one the environment
 * variable MMSIM_UNICORN names by its path (PyPI's unicorn 2.1.4 ships one:
 * it fixes 2.0.1's stale PC and slow stores, ../shared/notes/platform-facts.md). */
#ifndef UCDL_H
#define UCDL_H

#include <stddef.h>

/* 0 once libunicorn is loaded (the first call loads it); else -1 with one
 * line in err (the caller exits 3: an external failure). */
int ucdl_load(char *err, size_t errn);

#endif
