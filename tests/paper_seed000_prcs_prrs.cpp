#include <gtest/gtest.h>
#include "cyclide/surface.hpp"
TEST(Smoke, Builds) { SUCCEED(); }
