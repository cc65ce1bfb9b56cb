// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_COLUMN_STORE_H
#define CGAL_MODEL_REDUCTION_INTERNAL_COLUMN_STORE_H

/// \file Column_store.h
/// Where the converged vectors of a chain of slicing windows live, in double while windows
/// are kept orthogonal to them, in float32 once rounded for a basis stored in float32.

#include <CGAL/Model_reduction/internal/huge_pages.h>

#include <Eigen/Core>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Columns of large blocks mapped from the system in huge pages (a fresh allocation per
/// vector faulted its pages in one by one: 137k of the 192k page faults of the bunny's
/// basis).  A block is freed once all its columns are given back.  Addresses stay valid
/// until then.
template <class Scalar>
class Column_store
{
public:
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;

  /// A new column holding `v`.
  Scalar* add(const Eigen::Ref<const Vector>& v)
  {
    Scalar* column = add_columns(v.size(), 1).front().first;
    Eigen::Map<Vector>(column, v.size()) = v;
    return column;
  }

  /// A run of adjacent new columns (uninitialised): its first column and its length.
  typedef std::pair<Scalar*, Eigen::Index> Run;

  /// `count` new columns of `rows` entries, as few runs as the blocks allow.
  std::vector<Run> add_columns(Eigen::Index rows, Eigen::Index count)
  {
    std::vector<Run> runs;
    while(count > 0)
    {
      if(blocks_.empty() || !blocks_.back() || blocks_.back()->used == blocks_.back()->capacity ||
         blocks_.back()->rows != rows)
        blocks_.push_back(std::make_unique<Block>(rows, block_columns));
      Block& block = *blocks_.back();
      const Eigen::Index taken = std::min(count, block.capacity - block.used);
      runs.emplace_back(block.memory.data() + block.used * rows, taken);
      block.used += taken;
      block.live += taken;
      count -= taken;
    }
    return runs;
  }

  /// Gives `column` back; false if it is not one of this store's.  Its pages go back to the
  /// system at once (a basis copied out column by column then peaks at one copy, not one
  /// copy plus the blocks not yet emptied), except those of the last column added to a
  /// block while `keep_last`: the next `add` reuses it (a window gives back the columns it
  /// is about to recompute last first).
  bool release(const Scalar* column, bool keep_last = true)
  {
    for(std::unique_ptr<Block>& block : blocks_)
      if(block && block->holds(column))
      {
        const bool last = column == block->memory.data() + (block->used - 1) * block->rows;
        if(last) --block->used;
        if(--block->live == 0)
          block.reset(); // the next `add` starts a new block if it was the last
        else if(!(last && keep_last))
          discard_pages(const_cast<Scalar*>(column), sizeof(Scalar) * static_cast<std::size_t>(block->rows));
        return true;
      }
    return false;
  }

  /// Gives back the pages of the columns released last and kept for reuse.
  void discard_kept()
  {
    for(std::unique_ptr<Block>& block : blocks_)
      if(block)
        discard_pages(block->memory.data() + block->used * block->rows,
                      sizeof(Scalar) * static_cast<std::size_t>((block->capacity - block->used) * block->rows));
  }

private:
  // 64 columns: a few percent of the basis per block (few mappings, and little of a
  // block's tail left untouched when a chain ends).
  static constexpr Eigen::Index block_columns = 64;
  struct Block
  {
    Block(Eigen::Index rows, Eigen::Index capacity)
      : memory(static_cast<std::size_t>(rows * capacity)), rows(rows), capacity(capacity)
    {
    }
    Mapped_array<Scalar> memory;
    Eigen::Index rows, capacity, used = 0, live = 0;
    bool holds(const Scalar* column) const
    {
      return column >= memory.data() && column < memory.data() + rows * capacity;
    }
  };
  std::vector<std::unique_ptr<Block>> blocks_;
};

/// The double vectors windows are kept orthogonal to.
typedef Column_store<double> Vector_store;

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
