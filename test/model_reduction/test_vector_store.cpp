// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Pieces of a slicing chain: the store of its converged vectors (contents kept across
// blocks, a block freed exactly when all its columns are given back, foreign addresses
// refused, the pages of a column given back at once unless kept for reuse) and the block
// Gram-Schmidt kernel against its Krylov basis.

#include <CGAL/Model_reduction/internal/Lanczos_window.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace {

namespace MR = CGAL::Model_reduction;

TEST(VectorStore, KeepsEveryVectorAndFreesABlockOnceAllItsColumnsAreBack)
{
  const Eigen::Index n = 1000;
  const int count = 150; // blocks of 64: two full, one partly filled
  MR::internal::Vector_store store;
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

#if defined(__linux__)
// Pages wholly inside `column` (n doubles) that are resident, by mincore.
int resident_pages(const double* column, Eigen::Index n)
{
  const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(column) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(column + n)) & ~(page - 1);
  std::vector<unsigned char> in_core((end - begin) / page);
  if(mincore(reinterpret_cast<void*>(begin), end - begin, in_core.data()) != 0) return -1;
  int count = 0;
  for(unsigned char c : in_core) count += c & 1;
  return count;
}
#endif

TEST(VectorStore, GivesTheMemoryOfAColumnBackAtOnceUnlessKeptForTheNextAdd)
{
#if !defined(__linux__)
  GTEST_SKIP() << "page residency is read with Linux's mincore";
#else
  const Eigen::Index n = 1 << 16; // 512 KB a column: 127 whole pages or more
  const int count = 10;
  MR::internal::Vector_store store;
  const Eigen::MatrixXd vectors = Eigen::MatrixXd::Random(n, count);
  std::vector<double*> column(count);
  for(int i = 0; i < count; ++i) column[i] = store.add(vectors.col(i));
  const int whole_pages = resident_pages(column[3], n);
  ASSERT_GE(whole_pages, 127) << "a column just written should be resident";

  // A column in the middle: its pages go back, its neighbours keep their contents.
  EXPECT_TRUE(store.release(column[3]));
  EXPECT_EQ(resident_pages(column[3], n), 0);
  for(int i : {2, 4})
    EXPECT_EQ((Eigen::Map<Eigen::VectorXd>(column[i], n) - vectors.col(i)).norm(), 0.) << "column " << i;

  // The last column is kept for the next add, which reuses it.
  EXPECT_TRUE(store.release(column[9]));
  EXPECT_EQ(resident_pages(column[9], n), whole_pages);
  EXPECT_EQ(store.add(vectors.col(0)), column[9]);
  EXPECT_EQ((Eigen::Map<Eigen::VectorXd>(column[9], n) - vectors.col(0)).norm(), 0.);

  // Given back for good, the last column's pages go too; kept ones go with discard_kept.
  EXPECT_TRUE(store.release(column[9], false));
  EXPECT_EQ(resident_pages(column[9], n), 0);
  EXPECT_TRUE(store.release(column[8]));
  EXPECT_EQ(resident_pages(column[8], n), whole_pages);
  store.discard_kept();
  EXPECT_EQ(resident_pages(column[8], n), 0);
  EXPECT_EQ((Eigen::Map<Eigen::VectorXd>(column[7], n) - vectors.col(7)).norm(), 0.);
#endif
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
        const Eigen::MatrixXd C = MR::internal::project_out_of_columns(Q, first, count, Z);
        // Sums of n products of numbers below 1 in another order: a few n eps apart.
        const double tolerance = 1e-13 * static_cast<double>(n);
        ASSERT_EQ(C.rows(), count);
        ASSERT_EQ(C.cols(), block);
        EXPECT_LE((C - expected_C).cwiseAbs().maxCoeff(), tolerance) << "n " << n << " count " << count;
        EXPECT_LE((Z - expected_Z).cwiseAbs().maxCoeff(), tolerance * count) << "n " << n << " count " << count;
      }
}

} // namespace
