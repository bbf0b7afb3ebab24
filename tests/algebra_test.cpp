#include <gtest/gtest.h>
#include "cyclide/surface.hpp"
TEST(Smoke2, Builds) { SUCCEED(); }
