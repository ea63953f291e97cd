/* slalom.c - the turns' geometry in the half-cell grid (slalom.h).
 *
 * Derived for a right turn entering at (0, 0) heading N (or NE). The
 * corner is where the entry and exit lines meet; a turn of angle A with
 * radius R starts and ends R * tan(A / 2) from its corner, so the room on
 * each side of the corner bounds R:
 *   S90   corner (0,1), the cell centre: 1 half unit each side -> R <= 90 mm;
 *   F90   straight 1, arc of R = 2 half units (180 mm) about (2,1), straight 1:
 *         cell centre to cell centre through the cell diagonally ahead;
 *   F180  arc of R = 1 half unit (90 mm) about (1,0): through the two cells
 *         side by side, crossing the side between them at its middle;
 *   F45   corner (0,2): 2 half units before it, one diagonal step after;
 *   F135  corner (0,2), exit (1,1): one diagonal step (127 mm) after it;
 *   D45, D135 the reverses of F45 and F135;
 *   V90   corner (1,1): one diagonal step before and after. */
#include "slalom.h"

const slalom_geom_t slalom_geom[SLALOM_KINDS] = {
    [SLALOM_ORTHO] = {0},
    [SLALOM_DIAG] = {0},
    [SLALOM_S90] = {1, 1, 2, 0, 0, 1, 1, {{1, 1}}},
    [SLALOM_F90] = {3, 3, 2, 0, 0, 3, 3, {{0, 2}, {1, 3}, {3, 3}}},
    [SLALOM_F180] = {2, 0, 4, 0, 1, 0, 2, {{1, 1}, {2, 0}}},
    [SLALOM_F45] = {1, 3, 1, 0, 0, 2, 2, {{0, 2}, {1, 3}}},
    [SLALOM_F135] = {1, 1, 3, 0, 0, 2, 2, {{0, 2}, {1, 1}}},
    [SLALOM_D45] = {3, 1, 1, 1, 1, 1, 2, {{1, 1}, {3, 1}}},
    [SLALOM_D135] = {1, -1, 3, 1, 1, 1, 2, {{1, 1}, {1, -1}}},
    [SLALOM_V90] = {2, 0, 2, 1, 1, 1, 2, {{1, 1}, {2, 0}}},
};
