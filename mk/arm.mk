# arm.mk - our ARM test firmware for the Cortex-M core (sim/arm).

# ---- our ARM test firmware (test/firmware/arm: register-level C, our own startup and
# linker script) for the Cortex-M core's tests (test/unit/test_armcore.c,
# test/unit/test_armimage.c), built with Debian's arm-none-eabi-gcc ----
ARM_CC    := arm-none-eabi-gcc
ARM_FLAGS := -mcpu=cortex-m3 -mthumb -std=gnu99 -Os -g -Wall -Wextra -ffreestanding -nostdlib -Wl,--gc-sections
ARM_TEST_ELFS := $(B)/arm/coretest.elf $(B)/arm/fputest.elf $(B)/arm/soctest.elf $(B)/arm/boardtest.elf $(B)/arm/crashtest.elf
# fputest: the Cortex-M4F's FP context across exceptions (run on the stm32f405xg)
$(B)/arm/fputest.elf: ARM_FLAGS := -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard $(filter-out -mcpu=cortex-m3,$(ARM_FLAGS))
$(B)/arm/%.elf: test/firmware/arm/%.c test/firmware/arm/startup.c test/firmware/arm/armtest.h test/firmware/arm/link.ld | deps
	@mkdir -p $(dir $@)
	$(ARM_CC) $(ARM_FLAGS) -T test/firmware/arm/link.ld test/firmware/arm/startup.c $< -o $@
# Our STM32F405 test firmware (test/firmware/armf4: its own startup and linker
# script) for the F4 SoC's tests (test/unit/test_stm32f4_soc.c)
ARM4_FLAGS := -mcpu=cortex-m4 -mthumb -std=gnu99 -Os -g -Wall -Wextra -ffreestanding -nostdlib -Wl,--gc-sections
ARM_TEST_ELFS += $(B)/armf4/f4test.elf
$(B)/armf4/f4test.elf: test/firmware/armf4/f4test.c test/firmware/armf4/startup.c test/firmware/armf4/f4test.h test/firmware/armf4/link.ld | deps
	@mkdir -p $(dir $@)
	$(ARM_CC) $(ARM4_FLAGS) -T test/firmware/armf4/link.ld test/firmware/armf4/startup.c test/firmware/armf4/f4test.c -o $@
arm-test-firmware: $(ARM_TEST_ELFS)
.PHONY: arm-test-firmware
