// twice.h - a plain C++ file of the sketch folder, compiled beside the tabs
#pragma once

int twice(int x);
