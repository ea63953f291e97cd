/* mazegen.h - generator of legal competition mazes.
 *
 * A generated maze has a closed boundary; start (0,0) in the south-west
 * corner facing north with a wall on its east side; a centre goal (2x2 for
 * even sizes, 1 cell for odd, per axis) that is open inside and has exactly
 * one entrance; every post except the goal's centre post touches at least
 * one wall; the goal is reachable and there are several routes (loops),
 * except in 4x4 where the rules leave room for one route only.
 * Same (width, height, seed) -> the same maze, on every machine.
 */
#ifndef MAZEGEN_H
#define MAZEGEN_H

#include <stdint.h>
#include "truemaze.h"

#define MAZEGEN_MIN_SIZE 4
#define MAZEGEN_MAX_SIZE 32

/* Returns 0, or -1 if a size is outside MAZEGEN_MIN_SIZE..MAZEGEN_MAX_SIZE
 * (or above TRUEMAZE_MAX_SIZE). */
int mazegen_generate(truemaze_t *m, uint8_t width, uint8_t height, uint32_t seed);

#endif
