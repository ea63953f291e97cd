/* stm32f4_pwr.c - STM32F4 PWR_CR/PWR_CSR: RM0090 rev 19 5.4.1-5.4.2, RM0383
 * rev 3 5.4.1-5.4.2. Modeled: DBP (backup domain write access: stored, read
 * back), VOS, CSR VOSRDY (from the PLL's lock), CSBF/CWUF clearing SBF/WUF
 * (both 0: no standby or wake-up is modeled). Not modeled (a write that sets
 * them answers MMIO_UNMODELED): the low-power modes' bits LPDS, PDDS, FPDS
 * (and the F411's LPLVDS, MRLVDS, ADCDC1), the PVD (PVDE, PLS; PVDO reads
 * 0), the backup regulator (BRE; BRR reads 0), EWUP. */
#include "arm/stm32f4_pwr.h"

#include <stddef.h>

#include "arm/stm32f1_clk.h"
#include "arm/stm32f4_reg.h"

#define CR_DBP       (1u << 8)
#define CR_CWUF      (1u << 2)
#define CR_CSBF      (1u << 3)
#define CR_VOS_F405  (1u << 14)
#define CR_VOS_F411  (3u << 14)
#define CR_UNMODELED_F405 0x00000273u /* LPDS, PDDS, PVDE, PLS, FPDS */
#define CR_UNMODELED_F411 0x00002E73u /* and LPLVDS, MRLVDS, ADCDC1 */
#define CSR_VOSRDY   (1u << 14)
#define CSR_UNMODELED 0x00000300u     /* EWUP, BRE */

unsigned stm32f4_pwr_scale(const stm32f4_pwr_t *p)
{
    if (p->part == STM32F4_F405) return (p->cr & CR_VOS_F405) ? 1u : 2u;
    unsigned v = (p->cr >> 14) & 3u; /* 01 scale 3, 10 scale 2, 11 scale 1; 00 reserved: scale 3 */
    return v == 3u ? 1u : v == 2u ? 2u : 3u;
}

static uint32_t csr_now(const stm32f4_pwr_t *p)
{
    return p->csr | (stm32f4_rcc_pll_ready(p->rcc) ? CSR_VOSRDY : 0u);
}

static mmio_status_t pwr_read(void *self, uint32_t off, unsigned size, uint32_t *value)
{
    stm32f4_pwr_t *p = self;
    if (!stm32_access_ok(off, size) || (off & ~3u) > 4u) return MMIO_UNMODELED;
    *value = stm32_read_lanes((off & ~3u) == 0 ? p->cr : csr_now(p), off, size);
    return MMIO_OK;
}

static mmio_status_t pwr_write(void *self, uint32_t off, unsigned size, uint32_t value)
{
    stm32f4_pwr_t *p = self;
    if (!stm32_access_ok(off, size) || (off & ~3u) > 4u) return MMIO_UNMODELED;
    bool f405 = p->part == STM32F4_F405;
    if ((off & ~3u) == 4u) {
        uint32_t v = stm32f4_merge(p->csr, off, size, value);
        p->csr = v & CSR_UNMODELED;
        return (v & CSR_UNMODELED) ? MMIO_UNMODELED : MMIO_OK;
    }
    uint32_t v = stm32f4_merge(p->cr, off, size, value);
    uint32_t unmod = f405 ? CR_UNMODELED_F405 : CR_UNMODELED_F411;
    p->cr = v & (CR_DBP | unmod | (f405 ? CR_VOS_F405 : CR_VOS_F411)); /* CWUF/CSBF read 0 */
    return (v & unmod) ? MMIO_UNMODELED : MMIO_OK;
}

static void pwr_reset(void *self)
{
    stm32f4_pwr_t *p = self;
    p->cr = p->part == STM32F4_F405 ? 0x00004000u : 0x00008000u; /* RM0090 5.4.1, RM0383 5.4.1 */
    p->csr = 0;
}

const mmio_ops_t stm32f4_pwr_ops = { "PWR", pwr_read, pwr_write, NULL, NULL, pwr_reset };

void stm32f4_pwr_init(stm32f4_pwr_t *p, const stm32f4_rcc_t *rcc)
{
    *p = (stm32f4_pwr_t){ 0 };
    p->rcc = rcc;
    p->part = rcc->part;
    pwr_reset(p);
}
