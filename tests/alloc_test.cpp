#include <gtest/gtest.h>
TEST(Alloc, Placeholder) {}
int main(int c, char** v){ testing::InitGoogleTest(&c,v); return RUN_ALL_TESTS(); }
