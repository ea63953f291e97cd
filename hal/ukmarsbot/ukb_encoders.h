/* ukb_encoders.h - both wheel encoders on INT0/INT1 (hal_encoder and
 * hal_encoder_reset of hal.h are here). */
#ifndef UKB_ENCODERS_H
#define UKB_ENCODERS_H

void ukb_encoders_init(void);

#endif
