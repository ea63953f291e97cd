// Mouse - the whole mouse firmware (firmware/ of mmsim) on the Arduino,
// driving the simulated robot: run `mmsim --maze MAZE --serial /dev/ttyACM0`
// (framed protocol, 1,000,000 baud), then reset the board.
// A classic 16x16 contest by default; build with -DMM_MAZE_SIZE=N for an
// N x N maze (start in the south-west corner facing north, goal the centre),
// as the processor-in-the-loop test does (mmsim --avr).
#include <Micromouse.h>
#include "hal.h"
extern "C" { // the firmware's headers are plain C
#include "maze.h"
#include "mouse.h"
}

void setup()
{
    Serial.begin(1000000); // exact at 16 MHz (U2X)
#ifdef MM_MAZE_SIZE
    {
        maze_t m; // on the stack during setup only (292 bytes on the AVR)
        maze_init(&m, MM_MAZE_SIZE, MM_MAZE_SIZE);
        fw_set_maze(&m);
    }
#endif
    mm_mouse_begin(Serial, MM_FRAMED);
}

void loop()
{
    mm_mouse_loop(); // planning; control runs in the timer interrupt
}
