// scale.h - src/util, compiled and linked as the IDE does a sketch's src/
#pragma once
#include <stdint.h>

// value * percent / 100
long scale_percent(long value, int percent);
// 0 always: the one caller's use of the table below is dead code, which
// only link-time optimisation (across files) can see
int unused_mode();
// byte i of a 40,000-byte table in flash (two halves)
uint8_t table_byte(unsigned i);
