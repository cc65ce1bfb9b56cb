// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_ERRORS_H
#define CGAL_MODEL_REDUCTION_ERRORS_H

/// \file errors.h
/// The exceptions every package of the thesis throws.  Every check happens before any
/// output map is written, so a throwing call leaves the user's maps untouched.

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Model_reduction {

/// What is wrong with a mesh that an algorithm refuses.
enum class Mesh_defect {
  empty,                    ///< no faces
  non_triangle_face,        ///< a face with other than three vertices
  non_manifold_edge,        ///< an edge shared by more than two faces
  non_manifold_vertex,      ///< a vertex whose faces form more than one fan
  inconsistent_orientation, ///< two faces traverse their common edge in the same direction
  garbage,                  ///< removed elements still stored (call `collect_garbage()`)
  invalid_index,            ///< an element index outside `[0, n)` or repeated
  non_finite_coordinate,    ///< a NaN or infinite vertex coordinate
  degenerate_face,          ///< a face of (nearly) zero area; an algorithm may offer to mollify it
  unrepresentable_size      ///< a face whose area is too small or too large for a normal double (edges
                            ///< outside about 1e-150 to 1e150): scale the mesh
};

/// Thrown when a mesh cannot be processed; `defect()` says why and the message names the element.
class Invalid_mesh : public std::invalid_argument
{
public:
  Invalid_mesh(Mesh_defect defect, const std::string& what)
    : std::invalid_argument(what), defect_(defect) {}
  Mesh_defect defect() const { return defect_; }

private:
  Mesh_defect defect_;
};

/// Thrown for bad arguments other than the mesh: an input with NaN entries, a
/// vector of the wrong size, an out-of-range option, an unreadable file.
class Invalid_input : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// Thrown when a set of linear constraints cannot be met: a new constraint repeats or
/// contradicts earlier ones (its rows depend on theirs), or a reduced space is too small
/// to satisfy that many independent constraints.  The constraint is not added.
class Infeasible_constraints : public Invalid_input
{
public:
  Infeasible_constraints(const std::string& what, double independence, double residual)
    : Invalid_input(what), independence_(independence), residual_(residual) {}
  /// `sin^2` of the angle between the new rows and the span of the others (0: dependent).
  double independence() const { return independence_; }
  /// How far the requested value is from the one the other constraints already imply.
  double residual() const { return residual_; }

private:
  double independence_, residual_;
};

/// Thrown when a numerical self-check fails: a factorisation breaks down, an eigensolver
/// cannot prove its result complete, or a computed space does not have the dimension
/// the topology predicts.
class Numerical_failure : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Thrown when the caller's progress callback asks a long computation to stop; what was
/// computed is discarded.
class Cancelled : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace Model_reduction
} // namespace CGAL

#endif
