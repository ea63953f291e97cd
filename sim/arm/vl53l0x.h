/* vl53l0x.h - ST VL53L0X time-of-flight ranging sensor as an I2C slave
 * (stm32_i2c.h's interface, address 0x29): as far as the ST API's single
 * and back-to-back ranging register sequences need (sources and limits in
 * vl53l0x.c). The measured distance comes from the board's callback. */
#ifndef ARM_VL53L0X_H
#define ARM_VL53L0X_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define VL53L0X_I2C_ADDR 0x29u /* 7-bit (datasheet DS11555 "I2C interface": 0x52 as the write byte) */

/* The distance to the target the sensor sees at core cycle `cycle`, mm
 * (negative or NaN: no target). */
typedef double (*vl53l0x_range_fn)(void *ctx, uint64_t cycle);

typedef struct {
    const mmio_clocks_t *clk;
    vl53l0x_range_fn range;
    void *range_ctx;
    uint8_t reg[2][256];        /* pages 0 and 1 (register 0xFF selects) */
    bool have_index;
    uint8_t index;
    uint64_t last_cycle;        /* the cycle of the last access */
    double t_s;                 /* seconds at last_cycle */
    bool ranging, continuous;
    double range_end_s;         /* when the measurement in progress ends */
    unsigned long measurements;
} vl53l0x_t;

void vl53l0x_init(vl53l0x_t *v, const mmio_clocks_t *clk, vl53l0x_range_fn range, void *ctx);
void vl53l0x_reset(vl53l0x_t *v);
/* stm32_i2c_slave_t's functions */
bool vl53l0x_i2c_start(void *dev, bool read, uint64_t cycle);
bool vl53l0x_i2c_write(void *dev, uint8_t byte, uint64_t cycle);
uint8_t vl53l0x_i2c_read(void *dev, uint64_t cycle);
void vl53l0x_i2c_stop(void *dev, uint64_t cycle);

#endif
