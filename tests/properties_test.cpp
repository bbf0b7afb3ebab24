#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
RC_GTEST_PROP(Smoke, Trivial, (int a)) { RC_ASSERT(a == a); }
