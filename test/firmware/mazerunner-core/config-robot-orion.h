/* config-robot-orion.h - our configuration of mazerunner-core for a UK
 * contest, as its README says to set it up: config.h's EVENT = EVENT_UK,
 * whose goal is (7,7), and the ORION robot's sensor figures for EVENT_UK.
 *
 * The client's own files stay as they are. `make client-mazerunner` builds
 * the -uk image from a copy of its sketch folder with this header in place
 * of the client's config-robot-orion.h (mk/clients.mk). config.h includes
 * it after it has set EVENT (to EVENT_HOME) and GOAL and before anything
 * reads them but the robot's figures, so EVENT and GOAL are set here and
 * the client's own config-robot-orion.h (MRC_ROBOT_CONFIG, its path, from
 * the Makefile) is then read with EVENT_UK. */
#if !defined(EVENT) || !defined(EVENT_UK) || !defined(GOAL)
#error "mazerunner-core: this header replaces config-robot-orion.h, included by config.h after EVENT and GOAL"
#endif
#ifndef MRC_ROBOT_CONFIG
#error "mazerunner-core: MRC_ROBOT_CONFIG (the client's config-robot-orion.h) is not defined"
#endif

#undef EVENT
#define EVENT EVENT_UK
/* config.h's goal for every event but EVENT_HOME */
#undef GOAL
#define GOAL Location(7, 7)

#include MRC_ROBOT_CONFIG
