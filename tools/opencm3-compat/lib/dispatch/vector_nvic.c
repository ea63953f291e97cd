/* dispatch/vector_nvic.c - the family's generated vector_nvic.c (weak
 * aliases of its IRQ handlers, IRQ_HANDLERS for the vector table), included
 * by lib/cm3/vector.c. Ours: see tools/opencm3-compat/README.md. */
#if defined(STM32F0)
#	include "../stm32/f0/vector_nvic.c"
#elif defined(STM32F1)
#	include "../stm32/f1/vector_nvic.c"
#elif defined(STM32F2)
#	include "../stm32/f2/vector_nvic.c"
#elif defined(STM32F3)
#	include "../stm32/f3/vector_nvic.c"
#elif defined(STM32F4)
#	include "../stm32/f4/vector_nvic.c"
#elif defined(STM32F7)
#	include "../stm32/f7/vector_nvic.c"
#elif defined(STM32L0)
#	include "../stm32/l0/vector_nvic.c"
#elif defined(STM32L1)
#	include "../stm32/l1/vector_nvic.c"
#elif defined(STM32L4)
#	include "../stm32/l4/vector_nvic.c"
#else
#	error "mmsim's opencm3-compat dispatches the STM32 families only"
#endif
