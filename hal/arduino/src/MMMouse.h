/* MMMouse.h - runs the mouse firmware (firmware/, through hal/hal.h) on an
 * Arduino against the simulator: the HAL is served from mmLink, fw_tick
 * runs from a Timer1 interrupt at HAL_TICK_HZ (250 Hz on AVR: the float
 * control tick takes ~1.3 ms at 16 MHz, the link ~0.4 ms more), fw_loop
 * from loop().
 *
 * Interrupt discipline: the tick interrupt re-enables interrupts (so the
 * UART keeps receiving at 1 Mbaud) and is the only code that touches the
 * link: it reads the sensors in, runs fw_tick, then sends the motor
 * command and any queued log line. hal_* called from fw_loop only read
 * copies or queue. While fw_loop holds the tick (hal_tick_hold) the
 * interrupt leaves it due and hal_tick_release runs it from loop(). When the mouse is done (or gives up) the runner sends
 * RUN stop once, which ends the simulator's run (framed; in compat mode it
 * only stops the robot). */
#ifndef MM_MOUSE_H
#define MM_MOUSE_H

#include "MMLink.h"

/* After Serial.begin(1000000): attach the link (framed by default), run
 * fw_setup, start the tick. */
void mm_mouse_begin(Stream &s, uint8_t protocol = MM_FRAMED);
/* From loop(): one pass of fw_loop. */
void mm_mouse_loop();
/* Ticks skipped because the previous one had not finished. */
uint16_t mm_mouse_overruns();
/* The longest tick so far (link poll + fw_tick + sends), us; a tick that
 * outlasts the period wraps Timer1 and reads short (see overruns). */
uint16_t mm_mouse_worst_tick_us();

#endif
