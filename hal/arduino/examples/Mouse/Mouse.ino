// Mouse - the whole mouse firmware (firmware/ of mmsim) on the Arduino,
// driving the simulated robot: run `mmsim --maze MAZE --serial /dev/ttyACM0`
// (framed protocol, 1,000,000 baud), then reset the board.
#include <Micromouse.h>

void setup()
{
    Serial.begin(1000000); // exact at 16 MHz (U2X)
    mm_mouse_begin(Serial, MM_FRAMED);
}

void loop()
{
    mm_mouse_loop(); // planning; control runs in the timer interrupt
}
