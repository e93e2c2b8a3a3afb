#include <gtest/gtest.h>
#include "test_common.h"
TEST(Todo, Nothing) {}
