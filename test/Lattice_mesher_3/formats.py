#!/usr/bin/env python3
# Copyright (c) 2026 Lattice_mesher_3 developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The output formats read back by an independent reader (meshio): lattice-mesh writes one mesh
# as Medit .mesh, VTU and Gmsh .msh 4.1; each must give the same points, the same tetrahedra and
# the same boundary triangles, the triangles must be the faces in exactly one tetrahedron, and
# the VTU's theta_min must be the smallest dihedral angle of each tetrahedron (identity field).
# With --gmsh, Gmsh must open the .mesh and the .msh files and find the same elements in them.
#
#   formats.py --lattice-mesh BIN --out DIR [--gmsh BIN] [lattice-mesh arguments...]

import argparse
import os
import subprocess
import sys

import meshio
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep import dihedral_min  # noqa: E402


def cells(mesh, kind):
    blocks = [np.asarray(b.data) for b in mesh.cells if b.type == kind]
    return np.concatenate(blocks) if blocks else np.zeros((0, 3 if kind == 'triangle' else 4), int)


def sorted_rows(a):
    return np.array(sorted(map(tuple, np.sort(a, axis=1))))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--lattice-mesh', required=True)
    parser.add_argument('--out', required=True)
    parser.add_argument('--gmsh')
    args, rest = parser.parse_known_args()
    os.makedirs(args.out, exist_ok=True)
    names = {ext: os.path.join(args.out, 'formats' + ext) for ext in ('.mesh', '.vtu', '.msh')}
    command = [args.lattice_mesh] + rest + ['--quiet']
    for name in names.values():
        command += ['-o', name]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    meshes = {ext: meshio.read(name) for ext, name in names.items()}
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    medit = meshes['.mesh']
    points, tets = np.asarray(medit.points), cells(medit, 'tetra')
    triangles = cells(medit, 'triangle')
    check(len(tets) > 0 and len(triangles) > 0, 'the Medit file has tetrahedra and triangles')
    for ext in ('.vtu', '.msh'):
        m = meshes[ext]
        check(np.allclose(np.asarray(m.points), points, rtol=0, atol=1e-12), ext + ': the same points')
        check(np.array_equal(cells(m, 'tetra'), tets), ext + ': the same tetrahedra')
    check(np.array_equal(sorted_rows(cells(meshes['.msh'], 'triangle')), sorted_rows(triangles)),
          '.msh: the same boundary triangles as .mesh')
    # the triangles are the faces in exactly one tetrahedron
    faces = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 2, 3]], tets[:, [0, 1, 3]], tets[:, [0, 1, 2]]])
    unique, counts = np.unique(np.sort(faces, axis=1), axis=0, return_counts=True)
    check(np.array_equal(sorted_rows(unique[counts == 1]), sorted_rows(triangles)),
          'the triangles are the faces in one tetrahedron')
    # the surface patches: Medit references, Gmsh physical groups, the same for each triangle
    def labels(mesh, kind, key):
        return np.concatenate([d for block, d in zip(mesh.cells, mesh.cell_data.get(key, [])) if block.type == kind] or [[]])
    patches = labels(medit, 'triangle', 'medit:ref')
    check(len(patches) == len(triangles) and len(np.unique(patches)) > 1, '.mesh: the triangles carry several surface patches')
    msh = meshes['.msh']
    by_face = {tuple(sorted(t)): p for t, p in zip(cells(msh, 'triangle'), labels(msh, 'triangle', 'gmsh:physical'))}
    check(len(patches) == len(triangles) and all(by_face.get(tuple(sorted(t))) == p for t, p in zip(triangles, patches)),
          '.msh: each triangle in the physical group of its Medit patch')
    # the cell data of the VTU
    data = {k: np.concatenate(v) for k, v in meshes['.vtu'].cell_data.items()}
    check({'theta_min', 'rho', 'kappa'} <= set(data), '.vtu: theta_min, rho and kappa per tetrahedron')
    if 'theta_min' in data:
        check(np.allclose(data['theta_min'], dihedral_min(points[tets]), atol=1e-6), '.vtu: theta_min is the smallest dihedral angle')
    if 'rho' in data and 'kappa' in data:
        check(bool(np.all((data['rho'] > 0) & (data['rho'] <= 1 + 1e-9) & (data['kappa'] > 0) & (data['kappa'] <= 1 + 1e-9))),
              '.vtu: rho and kappa in (0, 1]')
    kinds = meshes['.vtu'].point_data.get('particle_kind')
    check(kinds is not None and len(kinds) == len(points) and set(np.unique(kinds)) <= {0, 1, 2, 3},
          '.vtu: a particle kind per vertex')
    if args.gmsh:   # Gmsh reads each file and writes what it read as MSH 4.1, which meshio reads
        for ext in ('.mesh', '.msh'):
            converted = os.path.join(args.out, 'gmsh' + ext.replace('.', '_') + '.msh')
            run = subprocess.run([args.gmsh, names[ext], '-0', '-format', 'msh41', '-o', converted],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            check(run.returncode == 0 and 'Error' not in run.stdout, 'Gmsh opens the ' + ext + ' file: ' + run.stdout[-300:])
            if run.returncode == 0:
                m = meshio.read(converted)
                check(len(cells(m, 'tetra')) == len(tets) and len(cells(m, 'triangle')) == len(triangles),
                      'Gmsh finds the tetrahedra and triangles of the ' + ext + ' file')
    print('%d points, %d tetrahedra, %d boundary triangles read back from .mesh, .vtu and .msh'
          % (len(points), len(tets), len(triangles)))
    for f in failures:
        print('FAILED: ' + f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
