/* dispatch/nvic.h - the family's generated nvic.h by the family's define
 * (libopencm3 builds each family with -DSTM32F1, -DSTM32F4, ...). Ours: see
 * tools/opencm3-compat/README.md. */
#if defined(STM32F0)
#	include <libopencm3/stm32/f0/nvic.h>
#elif defined(STM32F1)
#	include <libopencm3/stm32/f1/nvic.h>
#elif defined(STM32F2)
#	include <libopencm3/stm32/f2/nvic.h>
#elif defined(STM32F3)
#	include <libopencm3/stm32/f3/nvic.h>
#elif defined(STM32F4)
#	include <libopencm3/stm32/f4/nvic.h>
#elif defined(STM32F7)
#	include <libopencm3/stm32/f7/nvic.h>
#elif defined(STM32L0)
#	include <libopencm3/stm32/l0/nvic.h>
#elif defined(STM32L1)
#	include <libopencm3/stm32/l1/nvic.h>
#elif defined(STM32L4)
#	include <libopencm3/stm32/l4/nvic.h>
#else
#	error "mmsim's opencm3-compat dispatches the STM32 families only"
#endif
