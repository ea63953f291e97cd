/* vl53l0x.c - ST VL53L0X. Sources: datasheet DS11555 rev 2 (section 2.5
 * "I2C interface": 7-bit address 0x29, an 8-bit register index then data,
 * the index incrementing, multi-byte values most significant byte first;
 * 2.6 ranging: the default timing budget about 30 ms, table "ranging
 * accuracy": 1.2 m in default mode, 2 m in long range mode), and the
 * register names and values the ST API (VL53L0X API 1.0.2,
 * vl53l0x_device.h) and the Pololu library built on it use:
 * IDENTIFICATION_MODEL_ID 0xC0 = 0xEE, REVISION_ID 0xC2 = 0x10,
 * SYSRANGE_START 0x00 (bit 0 start, bit 1 back-to-back, bit 0 cleared by
 * the device once ranging starts), SYSTEM_INTERRUPT_CLEAR 0x0B,
 * RESULT_INTERRUPT_STATUS 0x13 (bits 2:0 = 4 "new sample ready" with the
 * default GPIO_HV_MUX config), RESULT_RANGE_STATUS 0x14 (bits 6:3 the
 * device range status, 11 = range valid), the range in mm at 0x14 + 10,
 * I2C_SLAVE_DEVICE_ADDRESS 0x8A, the "stop variable" at 0x91 of page 1
 * (0xFF = 0x01).
 * Modeled: the register file (every write stored, read back; page 1
 * through 0xFF), single and back-to-back ranging with the result after the
 * timing budget, its interrupt status and clear, out of range (beyond
 * 2000 mm or no target: range 8190, status 4 "phase fail", ours).
 * Not modeled: the timing budget the API programs through the sequence
 * step timeouts and VCSEL periods (a fixed 33 ms, the API's default), the
 * reference SPAD and VHV/phase calibrations (they run and end at once),
 * the SPAD information read from NVM (the model's values: ours), the
 * GPIO1 interrupt pin, range noise, signal rate and ambient (fixed
 * plausible values, ours), the address change (0x8A is stored, the
 * board's attach address stays). */
#include "arm/vl53l0x.h"

#include <math.h>

enum { SYSRANGE_START = 0x00, SYSTEM_INTERRUPT_CLEAR = 0x0B, RESULT_INTERRUPT_STATUS = 0x13,
       RESULT_RANGE_STATUS = 0x14, MODEL_ID = 0xC0, MODULE_TYPE = 0xC1, REVISION_ID = 0xC2, PAGE_SELECT = 0xFF,
       STOP_VARIABLE = 0x91 };
#define TIMING_BUDGET_S 0.033  /* ST API default, 33 ms */
#define MAX_RANGE_MM    2000.0 /* DS11555 ranging accuracy table: 2 m (long range) */
#define OUT_OF_RANGE_MM 8190u  /* what the device reports with no target (ours, as observed values are) */
#define STATUS_VALID    11u
#define STATUS_PHASE_FAIL 4u
#define NEW_SAMPLE_READY 0x04u

static void set_time(vl53l0x_t *v, uint64_t cycle)
{
    if (cycle > v->last_cycle && v->clk && v->clk->hclk) v->t_s += (double)(cycle - v->last_cycle) / v->clk->hclk;
    if (cycle > v->last_cycle) v->last_cycle = cycle;
}

/* The measurement that ended by now: its result registers. */
static void finish(vl53l0x_t *v)
{
    if (!v->ranging || v->t_s < v->range_end_s) return;
    if (v->continuous) { /* back-to-back: skip to the last measurement that ended (the earlier ones unread) */
        double k = floor((v->t_s - v->range_end_s) / TIMING_BUDGET_S);
        v->range_end_s += k * TIMING_BUDGET_S;
        v->measurements += (unsigned long)k;
    }
    uint64_t dk = v->clk ? (uint64_t)llround((v->t_s - v->range_end_s) * v->clk->hclk) : 0;
    uint64_t at = v->last_cycle >= dk ? v->last_cycle - dk : 0;
    double mm = v->range ? v->range(v->range_ctx, at) : -1.0;
    bool ok = mm >= 0.0 && mm <= MAX_RANGE_MM; /* also rejects NaN */
    unsigned r = ok ? (unsigned)lround(mm) : OUT_OF_RANGE_MM;
    uint8_t *p = v->reg[0];
    p[RESULT_RANGE_STATUS] = (uint8_t)((ok ? STATUS_VALID : STATUS_PHASE_FAIL) << 3);
    p[RESULT_RANGE_STATUS + 2] = 0x00;  /* effective SPAD count (ours: 8.0 in 8.8) */
    p[RESULT_RANGE_STATUS + 3] = 0x08;
    p[RESULT_RANGE_STATUS + 6] = 0x01;  /* signal rate (ours) */
    p[RESULT_RANGE_STATUS + 10] = (uint8_t)(r >> 8);
    p[RESULT_RANGE_STATUS + 11] = (uint8_t)r;
    p[RESULT_INTERRUPT_STATUS] = (p[RESULT_INTERRUPT_STATUS] & ~7u) | NEW_SAMPLE_READY;
    v->measurements++;
    if (v->continuous) v->range_end_s += TIMING_BUDGET_S;
    else v->ranging = false;
}

static void start_ranging(vl53l0x_t *v, uint8_t mode)
{
    if (mode & 1u) {
        v->ranging = true;
        v->continuous = (mode & 2u) != 0;
        v->range_end_s = v->t_s + TIMING_BUDGET_S;
        v->reg[0][SYSRANGE_START] = mode & ~1u; /* bit 0 clears once ranging starts */
    } else {
        v->reg[0][SYSRANGE_START] = mode;
        if (!(mode & 2u)) { v->ranging = v->continuous = false; } /* 0x00 stops back-to-back ranging */
    }
}

bool vl53l0x_i2c_start(void *dev, bool read, uint64_t cycle)
{
    vl53l0x_t *v = dev;
    set_time(v, cycle);
    finish(v);
    if (!read) v->have_index = false;
    return true;
}

bool vl53l0x_i2c_write(void *dev, uint8_t byte, uint64_t cycle)
{
    vl53l0x_t *v = dev;
    set_time(v, cycle);
    if (!v->have_index) { v->have_index = true; v->index = byte; return true; }
    uint8_t i = v->index++;
    if (i == PAGE_SELECT) { v->reg[0][PAGE_SELECT] = byte; return true; }
    unsigned page = v->reg[0][PAGE_SELECT] & 1u;
    if (page == 0 && i == SYSRANGE_START) { finish(v); start_ranging(v, byte); return true; }
    if (page == 0 && i == SYSTEM_INTERRUPT_CLEAR && (byte & 1u)) {
        finish(v);
        v->reg[0][RESULT_INTERRUPT_STATUS] &= ~7u;
        return true;
    }
    v->reg[page][i] = byte;
    return true;
}

uint8_t vl53l0x_i2c_read(void *dev, uint64_t cycle)
{
    vl53l0x_t *v = dev;
    set_time(v, cycle);
    finish(v);
    uint8_t i = v->index++;
    return i == PAGE_SELECT ? v->reg[0][PAGE_SELECT] : v->reg[v->reg[0][PAGE_SELECT] & 1u][i];
}

void vl53l0x_i2c_stop(void *dev, uint64_t cycle)
{
    vl53l0x_t *v = dev;
    set_time(v, cycle);
    v->have_index = false;
}

void vl53l0x_reset(vl53l0x_t *v)
{
    for (unsigned p = 0; p < 2; p++)
        for (unsigned i = 0; i < 256; i++) v->reg[p][i] = 0;
    v->reg[0][MODEL_ID] = 0xEEu;
    v->reg[0][MODULE_TYPE] = 0xAAu;
    v->reg[0][REVISION_ID] = 0x10u;
    v->reg[0][0x8A] = VL53L0X_I2C_ADDR; /* I2C_SLAVE_DEVICE_ADDRESS */
    v->reg[1][STOP_VARIABLE] = 0x3Cu;   /* ours: a part's value */
    v->ranging = v->continuous = false;
    v->have_index = false;
}

void vl53l0x_init(vl53l0x_t *v, const mmio_clocks_t *clk, vl53l0x_range_fn range, void *ctx)
{
    *v = (vl53l0x_t){ 0 };
    v->clk = clk;
    v->range = range;
    v->range_ctx = ctx;
    vl53l0x_reset(v);
}
