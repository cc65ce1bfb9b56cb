// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The store of a slicing chain's converged vectors: contents kept across blocks, a block
// freed exactly when all its columns are given back, foreign addresses refused.

#include <CGAL/Tangent_vector_fields/internal/Lanczos_window.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <vector>

namespace {

namespace TVF = CGAL::Tangent_vector_fields;

TEST(VectorStore, KeepsEveryVectorAndFreesABlockOnceAllItsColumnsAreBack)
{
  const Eigen::Index n = 1000;
  const int count = 150; // blocks of 64: two full, one partly filled
  TVF::internal::Vector_store store;
  Eigen::MatrixXd vectors = Eigen::MatrixXd::Random(n, count);
  std::vector<double*> column(count);
  for(int i = 0; i < count; ++i) column[i] = store.add(vectors.col(i));
  for(int i = 0; i < count; ++i)
    EXPECT_EQ((Eigen::Map<Eigen::VectorXd>(column[i], n) - vectors.col(i)).norm(), 0.) << "column " << i;

  // The first block's 64 columns, last first: each is the store's until the last is back.
  for(int i = 63; i >= 0; --i) EXPECT_TRUE(store.release(column[i])) << "column " << i;
  EXPECT_FALSE(store.release(column[0])) << "the first block should be gone";
  EXPECT_FALSE(store.release(column[63])) << "the first block should be gone";
  // The others are untouched by it.
  for(int i = 64; i < count; ++i)
    EXPECT_EQ((Eigen::Map<Eigen::VectorXd>(column[i], n) - vectors.col(i)).norm(), 0.) << "column " << i;

  // The partly filled last block is freed too, and a new vector then starts a new block.
  for(int i = 128; i < count; ++i) EXPECT_TRUE(store.release(column[i]));
  EXPECT_FALSE(store.release(column[128]));
  double* fresh = store.add(vectors.col(7));
  EXPECT_EQ((Eigen::Map<Eigen::VectorXd>(fresh, n) - vectors.col(7)).norm(), 0.);
  EXPECT_TRUE(store.release(column[64])); // the middle block is still there

  double outside = 0;
  EXPECT_FALSE(store.release(&outside));
}

} // namespace
