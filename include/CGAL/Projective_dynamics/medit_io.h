// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_MEDIT_IO_H
#define CGAL_PROJECTIVE_DYNAMICS_MEDIT_IO_H

/// \file medit_io.h
/// Tetrahedral meshes in Medit's ASCII `.mesh` format (the format of CGAL's Mesh_3 output,
/// TetGen's `-g`, Gmsh's `.mesh`): the sections `Vertices`, `Tetrahedra` and `Triangles`
/// are read (indices 1-based in the file, references ignored), others (`Edges`, `Corners`,
/// `Normals`, ...) skipped; `#` starts a comment.

#include <CGAL/Projective_dynamics/Tet_mesh.h>

#include <iosfwd>
#include <string>

namespace CGAL {
namespace Projective_dynamics {

/// Reads a Medit mesh from `in`; `name` is how messages call the source (a file name).
/// \throws Invalid_input naming the line for a malformed file: no `MeshVersionFormatted`,
///         a dimension other than 3, a count or number that does not parse, a section cut
///         short, an index outside `[1, number of vertices]`, a non-finite coordinate.
///         The mesh is not checked further (call `check_tet_mesh`).
Tet_mesh read_medit(std::istream& in, const std::string& name = "input");
/// Reads the Medit file at `path`. \throws Invalid_input as above, or if it cannot be opened.
Tet_mesh read_medit(const std::string& path);

/// Writes `mesh` in Medit's format (version 2: doubles written with 17 significant digits, so
/// that reading gives back the same numbers), every reference 0.
/// \throws Invalid_input if the file cannot be written.
void write_medit(std::ostream& out, const Tet_mesh& mesh);
void write_medit(const std::string& path, const Tet_mesh& mesh);

} // namespace Projective_dynamics
} // namespace CGAL

#endif
