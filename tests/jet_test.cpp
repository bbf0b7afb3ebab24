// The core is generic in its scalar: Ceres Jets flow through the PRCS and
// PRRS frames (what the optimizer tier will differentiate). The derivative
// of the spine with respect to u by a Jet equals the series derivative.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "cyclide/prcs.hpp"
#include "cyclide/prrs.hpp"

using namespace cyclide;
using J = ceres::Jet<double, 1>;


TEST(Jets, FlowThroughThePrcsSpine) {
  RationalCurve p1, p2;
  const double c1[] = {0, 0, 0, 1, 0, 0, 0.1, 0.2, 0, 0.05, 0, 0.1};
  const double c2[] = {0, 0, 1, 2, 1, 0, 0, 0.1, 0.2, 0.1, 0.05, 0};
  ASSERT_EQ(make_polynomial_curve(3, c1, p1), Status::ok);
  ASSERT_EQ(make_polynomial_curve(3, c2, p2), Status::ok);
  for (double u : {-0.3, 0.1, 0.4}) {
    Vec3<Taylor<J, 0>> sj;
    ASSERT_EQ(prcs_spine<0>(p1, p2, J(u, 0), 1.0, sj), Status::ok);
    Vec3<Taylor<double, 1>> sd;
    ASSERT_EQ(prcs_spine<1>(p1, p2, u, 1.0, sd), Status::ok);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(sj[k].c[0].a, sd[k].c[0], 1e-14);
      EXPECT_NEAR(sj[k].c[0].v[0], sd[k].c[1], 1e-12);  // ds/du by the Jet
    }
  }
}

TEST(Jets, FlowThroughThePrrsFrame) {
  RationalCurve l1, l2, l3;
  ASSERT_EQ(make_line({0, 0, 0}, {1, 0, 0}, l1), Status::ok);
  ASSERT_EQ(make_line({0, 0, 0}, {2, 1, 0}, l2), Status::ok);
  ASSERT_EQ(make_line({1, 1, 1}, {-1, 2, 0}, l3), Status::ok);
  CircleFrame<Taylor<J, 0>> Fj;
  CircleFrame<Taylor<double, 1>> Fd;
  ASSERT_EQ(prrs_frame<0>(l1, l2, l3, J(0.5, 0), Fj), Status::ok);
  ASSERT_EQ(prrs_frame<1>(l1, l2, l3, 0.5, Fd), Status::ok);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(Fj.o[k].c[0].v[0], Fd.o[k].c[1], 1e-12);
}
