// QpProblem storage and status names.
#include "control/qp/qp_problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "config/input_error.hpp"
#include "control/qp/qp_result.hpp"

namespace handover::control {
namespace {

TEST(QpProblem, ReserveSizesAndClearsStorage) {
  QpProblem p;
  p.n_eq = 3;
  p.n_in = 4;
  p.reserve(13, 7, 40);
  EXPECT_EQ(p.n, 13);
  EXPECT_EQ(p.n_eq, 0);
  EXPECT_EQ(p.n_in, 0);
  EXPECT_EQ(p.capacityEq(), 7);
  EXPECT_EQ(p.capacityIn(), 40);
  EXPECT_EQ(p.H.rows(), 13);
  EXPECT_EQ(p.H.cols(), 13);
  EXPECT_EQ(p.A_eq.cols(), 13);
  EXPECT_EQ(p.C.cols(), 13);
  EXPECT_EQ(p.b_eq.size(), 7);
  EXPECT_EQ(p.c_lb.size(), 40);
  EXPECT_EQ(p.c_ub.size(), 40);
  EXPECT_TRUE(p.H.isZero(0.0));
  EXPECT_TRUE(p.g.isZero(0.0));
  for (int i = 0; i < 40; ++i) {
    EXPECT_LE(p.c_lb[i], -kQpInfinity);
    EXPECT_GE(p.c_ub[i], kQpInfinity);
  }
  for (int j = 0; j < 13; ++j) {
    EXPECT_LE(p.x_lb[j], -kQpInfinity);
    EXPECT_GE(p.x_ub[j], kQpInfinity);
  }
}

TEST(QpProblem, ReserveRejectsBadSizesWithAMessage) {
  QpProblem p;
  try {
    p.reserve(0, 1, 1);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("num_vars=0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(p.reserve(3, -1, 0), InputError);
  EXPECT_THROW(p.reserve(3, 0, -2), InputError);
}

TEST(QpProblem, StatusAndRowKindNamesAreDistinct) {
  std::set<std::string> names;
  for (QpStatus s : {QpStatus::kOptimal, QpStatus::kInfeasible, QpStatus::kMaxIterations,
                     QpStatus::kInvalidProblem})
    names.insert(toString(s));
  EXPECT_EQ(names.size(), 4u);
  EXPECT_EQ(std::string(toString(QpStatus::kOptimal)), "optimal");
  EXPECT_EQ(std::string(toString(QpStatus::kInfeasible)), "infeasible");
  std::set<std::string> kinds;
  for (QpRowKind k : {QpRowKind::kEquality, QpRowKind::kRowLower, QpRowKind::kRowUpper,
                      QpRowKind::kRowFixed, QpRowKind::kBoundLower, QpRowKind::kBoundUpper,
                      QpRowKind::kBoundFixed})
    kinds.insert(toString(k));
  EXPECT_EQ(kinds.size(), 7u);
}

}  // namespace
}  // namespace handover::control
