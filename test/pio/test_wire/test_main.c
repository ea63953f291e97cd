/* test_main.c - `pio test -e native`: the wire codec's shared vectors with
 * PlatformIO's Unity (the cmocka suite in test/ is what `make test` runs). */
#include <unity.h>

#include "../../unit/wire_vectors.c" /* the shared vectors, one file for every build */

void setUp(void) {}
void tearDown(void) {}

static void test_vectors(void)
{
    const char *first = 0;
    unsigned bad = wire_vectors_check(&first);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, bad, first ? first : "");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_vectors);
    return UNITY_END();
}
