// twice.cpp - x * 2
#include "twice.h"

int twice(int x) { return x * 2; }
