/* search.h - the search: explore until the run path is proven, then home
 * to the start (search.c), on drive.h's moves. */
#ifndef SEARCH_H
#define SEARCH_H

#include "drive.h"

/* One loop of the search: sets dr->st.mode to MOUSE_TO_RUN when the search
 * is over, MOUSE_NO_GOAL when the goal cannot be reached. */
void search_step(drive_t *dr);

#endif
