/* wire_vectors.h - shared test vectors of the wire protocol (hal/wire):
 * message <-> exact bytes, framed and compat. Used by the host test
 * (test/unit/test_wire.c) and by the AVR self-test (test/firmware/avr/avr_wire.c, run in
 * simavr), so both ends are checked against the same bytes. The framed
 * bytes were computed by an independent implementation (Python: COBS,
 * CRC-16/CCITT-FALSE) when the vectors were written. */
#ifndef WIRE_VECTORS_H
#define WIRE_VECTORS_H

#include <stdint.h>

#include "wire.h"

typedef struct {
    const char *name;
    wire_msg_t msg;
    const uint8_t *bytes;
    uint8_t len;
} wire_vector_t;

extern const wire_vector_t wire_vectors_framed[];
extern const uint8_t wire_vectors_framed_count;
/* compat vectors: encoded from a fresh wire_compat_tx_t (range 1200 mm), each on its own */
extern const wire_vector_t wire_vectors_compat[];
extern const uint8_t wire_vectors_compat_count;

/* Check every vector: encode -> bytes, bytes -> decode -> message, both
 * modes. Returns the number of failed checks; names the first failure in
 * *first (NULL if none). */
unsigned wire_vectors_check(const char **first);

#endif
