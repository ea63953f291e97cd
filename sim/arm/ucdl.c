/* ucdl.c - libunicorn through dlopen (see ucdl.h). */
#include "ucdl.h"

#include <dlfcn.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unicorn/unicorn.h>

#define UCDL_SONAME "libunicorn.so.2"
#define UCDL_ENV "MMSIM_UNICORN"   /* another libunicorn.so.2 by its path (PyPI unicorn 2.1.4's: see ucdl.h) */
#define UCDL_CTL_ARGS_MAX 4u /* uc_ctl's argument count is bits 26-29 of the control (UC_CTL) */

static struct {
    void *lib;
    uc_err (*open)(uc_arch, uc_mode, uc_engine **);
    uc_err (*close)(uc_engine *);
    uc_err (*ctl)(uc_engine *, uc_control_type, ...);
    const char *(*strerror)(uc_err);
    uc_err (*reg_write)(uc_engine *, int, const void *);
    uc_err (*reg_read)(uc_engine *, int, void *);
    uc_err (*reg_write_batch)(uc_engine *, int *, void *const *, int);
    uc_err (*reg_read_batch)(uc_engine *, int *, void **, int);
    uc_err (*mem_read)(uc_engine *, uint64_t, void *, size_t);
    uc_err (*emu_start)(uc_engine *, uint64_t, uint64_t, uint64_t, size_t);
    uc_err (*emu_stop)(uc_engine *);
    uc_err (*hook_add)(uc_engine *, uc_hook *, int, void *, void *, uint64_t, uint64_t, ...);
    uc_err (*mem_map_ptr)(uc_engine *, uint64_t, size_t, uint32_t, void *);
    uc_err (*mmio_map)(uc_engine *, uint64_t, size_t, uc_cb_mmio_read_t, void *, uc_cb_mmio_write_t, void *);
} api;

/* A function pointer from a data pointer (dlsym's), through memcpy: the C standard has no conversion between them. */
#define RESOLVE(field, name)                                    \
    do {                                                        \
        void *sym = dlsym(lib, name);                           \
        if (!sym) { missing = name; break; }                    \
        memcpy(&api.field, &sym, sizeof sym);                   \
    } while (0)

int ucdl_load(char *err, size_t errn)
{
    if (api.lib) return 0;
    const char *path = getenv(UCDL_ENV);
    if (!path || !*path) path = UCDL_SONAME;
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!lib) return snprintf(err, errn, "mmsim: the ARM core needs %s (Debian's libunicorn2): %s", UCDL_SONAME, dlerror()), -1;
    const char *missing = NULL;
    RESOLVE(open, "uc_open"); RESOLVE(close, "uc_close"); RESOLVE(ctl, "uc_ctl"); RESOLVE(strerror, "uc_strerror");
    RESOLVE(reg_write, "uc_reg_write"); RESOLVE(reg_read, "uc_reg_read"); RESOLVE(reg_write_batch, "uc_reg_write_batch");
    RESOLVE(reg_read_batch, "uc_reg_read_batch"); RESOLVE(mem_read, "uc_mem_read"); RESOLVE(emu_start, "uc_emu_start");
    RESOLVE(emu_stop, "uc_emu_stop"); RESOLVE(hook_add, "uc_hook_add"); RESOLVE(mem_map_ptr, "uc_mem_map_ptr");
    RESOLVE(mmio_map, "uc_mmio_map");
    if (missing) {
        snprintf(err, errn, "mmsim: %s has no %s (the ARM core needs unicorn 2)", UCDL_SONAME, missing);
        dlclose(lib);
        return -1;
    }
    api.lib = lib;
    return 0;
}

uc_err uc_open(uc_arch arch, uc_mode mode, uc_engine **uc) { return api.open ? api.open(arch, mode, uc) : UC_ERR_HANDLE; }
uc_err uc_close(uc_engine *uc) { return api.close(uc); }
const char *uc_strerror(uc_err code) { return api.strerror ? api.strerror(code) : "libunicorn not loaded"; }
uc_err uc_reg_write(uc_engine *uc, int regid, const void *value) { return api.reg_write(uc, regid, value); }
uc_err uc_reg_read(uc_engine *uc, int regid, void *value) { return api.reg_read(uc, regid, value); }
uc_err uc_reg_write_batch(uc_engine *uc, int *regs, void *const *vals, int count) { return api.reg_write_batch(uc, regs, vals, count); }
uc_err uc_reg_read_batch(uc_engine *uc, int *regs, void **vals, int count) { return api.reg_read_batch(uc, regs, vals, count); }
uc_err uc_mem_read(uc_engine *uc, uint64_t address, void *bytes, size_t size) { return api.mem_read(uc, address, bytes, size); }
uc_err uc_emu_start(uc_engine *uc, uint64_t begin, uint64_t until, uint64_t timeout, size_t count)
{
    return api.emu_start(uc, begin, until, timeout, count);
}
uc_err uc_emu_stop(uc_engine *uc) { return api.emu_stop(uc); }
uc_err uc_mem_map_ptr(uc_engine *uc, uint64_t address, size_t size, uint32_t perms, void *ptr)
{
    return api.mem_map_ptr(uc, address, size, perms, ptr);
}
uc_err uc_mmio_map(uc_engine *uc, uint64_t address, size_t size, uc_cb_mmio_read_t read_cb, void *user_data_read,
                   uc_cb_mmio_write_t write_cb, void *user_data_write)
{
    return api.mmio_map(uc, address, size, read_cb, user_data_read, write_cb, user_data_write);
}

/* The variadic ones: UC_HOOK_INSN takes the instruction as one more int; uc_ctl's arguments are read
 * as libunicorn reads them (an int for the CPU model, 64-bit words otherwise: addresses, sizes). */
uc_err uc_hook_add(uc_engine *uc, uc_hook *hh, int type, void *callback, void *user_data, uint64_t begin, uint64_t end, ...)
{
    if (!(type & UC_HOOK_INSN)) return api.hook_add(uc, hh, type, callback, user_data, begin, end);
    va_list ap;
    va_start(ap, end);
    int insn = va_arg(ap, int);
    va_end(ap);
    return api.hook_add(uc, hh, type, callback, user_data, begin, end, insn);
}

uc_err uc_ctl(uc_engine *uc, uc_control_type control, ...)
{
    uint64_t a[UCDL_CTL_ARGS_MAX] = { 0 };
    unsigned nr = ((unsigned)control >> 26) & 0xFu;
    va_list ap;
    va_start(ap, control);
    if (((unsigned)control & 0xFFFFu) == UC_CTL_CPU_MODEL && nr == 1 && ((unsigned)control >> 30) == UC_CTL_IO_WRITE) {
        int model = va_arg(ap, int);
        va_end(ap);
        return api.ctl(uc, control, model);
    }
    for (unsigned i = 0; i < nr && i < UCDL_CTL_ARGS_MAX; i++) a[i] = va_arg(ap, uint64_t);
    va_end(ap);
    return api.ctl(uc, control, a[0], a[1], a[2], a[3]);
}
