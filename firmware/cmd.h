/* cmd.h - external command mode (mmsim --mms; mouse.h's mouse_cmd_* are
 * these on the mouse's drive_t): the caller orders each move. The moves
 * reuse the search's primitives (drive.h): a straight senses the walls of
 * every cell it enters, centres on the side walls, aligns on a wall ahead
 * and ends with a front fix; turns are drive_turn's in-place turns. */
#ifndef CMD_H
#define CMD_H

#include "drive.h"

void cmd_mode(drive_t *dr);
uint8_t cmd_status(drive_t *dr);
uint16_t cmd_moved(void);
uint8_t cmd_edge(void);
int cmd_forward(drive_t *dr, uint16_t halves);
int cmd_turn(drive_t *dr, int8_t q);
int cmd_turn45(drive_t *dr, int8_t e);
uint8_t cmd_heading8(drive_t *dr);
void cmd_reset(drive_t *dr);
/* One loop of command mode (fw_loop in MOUSE_COMMAND). */
void cmd_step(drive_t *dr);

#endif
