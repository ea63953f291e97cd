/* mpu6500.h - InvenSense MPU-6500 6-axis motion sensor as an SPI slave
 * (stm32f1_spi.h's interface): the registers firmware uses, gyro Z from the
 * physics' yaw rate with the datasheet's noise and zero-rate offset. Sources
 * in mpu6500.c: the MPU-6500 Product Specification (PS-MPU-6500A-01 rev
 * 1.1) and Register Map (RM-MPU-6500A-00 rev 2.1).
 * The same register engine is the MPU-6050 (its own figures: WHO_AM_I
 * 0x68, SLEEP at reset, noise, ZRO, DLPF, temperature scale) on I2C
 * (stm32_i2c.h's slave interface, address 0x68 or 0x69). */
#ifndef ARM_MPU6500_H
#define ARM_MPU6500_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"
#include "world/rng.h"

/* The noise stream of MPU-6500 number `index` (rng.h's streams stop below 400). */
#define MPU6500_RNG_STREAM 400u

/* The true z rate the chip's axis turns at, rad/s, at core cycle `cycle`. */
typedef double (*mpu6500_rate_fn)(void *ctx, uint64_t cycle);

/* A part's figures (mpu6500.c: mpu6500_part_6500, mpu6500_part_6050). */
typedef struct mpu6500_part mpu6500_part_t;
extern const mpu6500_part_t mpu6500_part_6500;
extern const mpu6500_part_t mpu6500_part_6050;

typedef struct {
    const mpu6500_part_t *part;
    const mmio_clocks_t *clk;   /* HCLK: core cycles to seconds */
    mpu6500_rate_fn rate;
    void *rate_ctx;
    rng_t rng;
    double zro_dps;             /* this part's zero-rate output, drawn at init, deg/s */
    uint8_t reg[128];
    /* the serial interface */
    bool selected;              /* nCS low */
    bool have_addr, reading;
    uint8_t addr;
    /* the gyro's output samples */
    uint64_t last_cycle;        /* the cycle of the last access */
    double t_s;                 /* seconds at last_cycle */
    int64_t sample;             /* index of the held sample, -1: none */
    double z_dps;               /* the held sample's rate, deg/s, before the user offset */
    /* accesses to registers the model does not implement (FIFO, I2C master,
     * interrupts, self-test, wake-on-motion ...): counted, for the board's report */
    unsigned long unmodeled_count;
    uint8_t unmodeled_map[16];  /* bit r: register r was accessed */
} mpu6500_t;

void mpu6500_init(mpu6500_t *m, const mmio_clocks_t *clk, mpu6500_rate_fn rate, void *rate_ctx,
                  uint64_t seed, unsigned index);
/* An MPU-6050 (PS-MPU-6000A-00 rev 3.4, RM-MPU-6000A-00 rev 4.2) on I2C. */
void mpu6050_init(mpu6500_t *m, const mmio_clocks_t *clk, mpu6500_rate_fn rate, void *rate_ctx,
                  uint64_t seed, unsigned index);
/* The I2C slave side (stm32_i2c_slave_t): a START addressed to the chip
 * (read: the R/W bit), a byte written (the first of a write transfer is the
 * register address, PS 9.3 "I2C communications protocol"), a byte read
 * (the address incrementing), the STOP. Each acknowledges with true. */
bool mpu6500_i2c_start(void *dev, bool read, uint64_t cycle);
bool mpu6500_i2c_write(void *dev, uint8_t byte, uint64_t cycle);
uint8_t mpu6500_i2c_read(void *dev, uint64_t cycle);
void mpu6500_i2c_stop(void *dev, uint64_t cycle);
/* Power-on reset: the register defaults (the part's offset stays). */
void mpu6500_reset(mpu6500_t *m);
/* nCS, wired by the board from a GPIO output: low selects the chip; a rising
 * edge ends the transaction. */
void mpu6500_select(mpu6500_t *m, bool ncs_level);
/* stm32_spi_slave_t.exchange */
uint8_t mpu6500_exchange(void *dev, uint8_t mosi, uint64_t cycle);
/* Whether register reg (0..127) was accessed though the model does not implement it. */
bool mpu6500_unmodeled(const mpu6500_t *m, unsigned reg);
/* The white noise's standard deviation per sample at the configured filter, deg/s. */
double mpu6500_sigma_dps(const mpu6500_t *m);
/* Sensitivity at the configured full scale, LSB per deg/s. */
double mpu6500_lsb_per_dps(const mpu6500_t *m);

#endif
