// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Pieces of a slicing chain: the store of its converged vectors (contents kept across
// blocks, a block freed exactly when all its columns are given back, foreign addresses
// refused) and the block Gram-Schmidt kernel against its Krylov basis.

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

// The hand-vectorised projection against columns of a basis equals the plain dense
// products C = Q_J^T Z, Z - Q_J C, for row counts across the kernel's 8192-row panels, column
// counts that are not multiples of its four, and a column range starting inside the basis.
TEST(BlockGramSchmidt, ProjectionEqualsTheDenseProducts)
{
  for(const Eigen::Index n : {5, 8192, 20001})
    for(const int block : {4, 3})
      for(const Eigen::Index count : {1, 4, 7, 13})
      {
        const Eigen::Index first = 2;
        const Eigen::MatrixXd Q = Eigen::MatrixXd::Random(n, first + count + 3);
        const Eigen::MatrixXd Z0 = Eigen::MatrixXd::Random(n, block);
        const Eigen::MatrixXd expected_C = Q.middleCols(first, count).transpose() * Z0;
        const Eigen::MatrixXd expected_Z = Z0 - Q.middleCols(first, count) * expected_C;
        Eigen::MatrixXd Z = Z0;
        const Eigen::MatrixXd C = TVF::internal::project_out_of_columns(Q, first, count, Z);
        // Sums of n products of numbers below 1 in another order: a few n eps apart.
        const double tolerance = 1e-13 * static_cast<double>(n);
        ASSERT_EQ(C.rows(), count);
        ASSERT_EQ(C.cols(), block);
        EXPECT_LE((C - expected_C).cwiseAbs().maxCoeff(), tolerance) << "n " << n << " count " << count;
        EXPECT_LE((Z - expected_Z).cwiseAbs().maxCoeff(), tolerance * count) << "n " << n << " count " << count;
      }
}

} // namespace
