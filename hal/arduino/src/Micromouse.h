/* Micromouse.h - the library's one header: the serial link to the mmsim
 * simulator, the paper's user API, and the runner for the mouse firmware. */
#ifndef MICROMOUSE_H
#define MICROMOUSE_H

#include "MMLink.h"
#include "MMApi.h"
#include "MMMouse.h"

#endif
