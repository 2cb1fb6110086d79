#!/usr/bin/env python3
# Copyright (c) 2026 Lattice_mesher_3 developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The sweep: meshes every surface of a folder with lattice-mesh, as a new user would, and checks
# each result with a reader and checks of its own (meshio, numpy), not with the package's code:
#   - an input whose edges (after merging coincident points) are each in an even number of faces
#     is closed and must give a valid mesh: every tetrahedron positive, each triangle in at most
#     two tetrahedra, the boundary a closed manifold (each boundary edge in exactly two boundary
#     triangles, once in each direction), the smallest dihedral angle at least --min-angle
#     degrees, the Hausdorff distance to the input (measured by lattice-mesh, --stats) at most
#     --hausdorff times l* and, sample by sample, at most --hausdorff times the mesh's local size
#     (the longest boundary edge at the sample); lattice-mesh must warn of a part lost exactly when
#     that local ratio exceeds 1.5;
#   - any other input is open and must be refused with a message naming the problem;
#   - no crash, no time-out.
# Models listed in --known-failures (a line "model: reason") may fail the check against the
# local size without failing the sweep (any other failed check still fails it: a crash, a
# time-out, a refusal, an invalid mesh, an angle or a distance over l* past its threshold, a
# missing warning); a listed model that now passes is reported, so that the list only shrinks.
#
#   sweep.py --lattice-mesh BIN --models DIR [--vertices N] [--shard I/N] [--out DIR] [--csv FILE]
#            [--only a.off,b.off] [--option=--cells-across --option=3 ...]

import argparse
import csv
import json
import os
import signal
import subprocess
import sys
import time

import meshio
import numpy as np


def read_off(path):
    """Points and polygons of an OFF file, line by line: comments, [C][N]OFF headers, the counts
    on the header line or the next, colours after a vertex's coordinates or a face's indices."""
    lines = (l.split('#', 1)[0].split() for l in open(path, errors='replace'))
    lines = [l for l in lines if l]
    if not lines or not lines[0][0].endswith('OFF'):
        raise ValueError('not an OFF file')
    counts = lines[0][1:] or lines[1]
    start = 1 if lines[0][1:] else 2
    nv, nf = int(counts[0]), int(counts[1])
    points = np.array([[float(w) for w in l[:3]] for l in lines[start:start + nv]], dtype=float)
    polygons = [[int(w) for w in l[1:1 + int(l[0])]] for l in lines[start + nv:start + nv + nf]]
    return points, polygons


def read_ascii_ply(path):
    """Points and polygons of an ASCII PLY file with any other elements and properties."""
    lines = open(path, errors='replace').read().splitlines()
    elements, end = [], lines.index('end_header')
    for l in lines[:end]:
        w = l.split()
        if w[:1] == ['format'] and w[1] != 'ascii':
            raise ValueError('binary PLY')
        if w[:1] == ['element']:
            elements.append((w[1], int(w[2]), []))
        elif w[:1] == ['property']:
            elements[-1][2].append(w[-1])
    pos, points, polygons = end + 1, None, []
    for name, count, props in elements:
        rows = [l.split() for l in lines[pos:pos + count]]
        pos += count
        if name == 'vertex':
            xyz = [props.index(c) for c in 'xyz']
            points = np.array([[float(r[i]) for i in xyz] for r in rows], dtype=float)
        elif name == 'face':   # the vertex list first
            polygons = [[int(x) for x in r[1:1 + int(r[0])]] for r in rows]
    return points, polygons


def read_surface(path):
    """Points and triangles of a surface file (polygons fanned), coincident points merged."""
    if path.lower().endswith('.off'):
        points, polygons = read_off(path)
    else:
        try:   # meshio's PLY reader stops the program (SystemExit) on elements it does not know
            points, polygons = read_ascii_ply(path)
        except (ValueError, IndexError):
            m = meshio.read(path)
            points = np.asarray(m.points, dtype=float)
            polygons = [list(row) for block in m.cells for row in np.asarray(block.data)]
    faces = [(poly[0], poly[k], poly[k + 1]) for poly in polygons for k in range(1, len(poly) - 1)]
    if not faces:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    _, first, inverse = np.unique(points, axis=0, return_index=True, return_inverse=True)
    return points[first], inverse.reshape(-1)[np.array(faces, dtype=np.int64)]


def is_closed(path):
    """Every edge of a non-degenerate triangle in an even number of triangles."""
    try:
        _, tris = read_surface(path)
    except Exception:
        return None   # unreadable: must be refused
    tris = tris[(tris[:, 0] != tris[:, 1]) & (tris[:, 1] != tris[:, 2]) & (tris[:, 0] != tris[:, 2])]
    if len(tris) == 0:
        return False
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(np.all(counts % 2 == 0))


def dihedral_min(p):
    """Smallest of the six dihedral angles (degrees) of each tetrahedron, p: (n, 4, 3)."""
    faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]   # face i opposite vertex i
    n = [np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a]) for a, b, c in faces]
    n = [v / np.linalg.norm(v, axis=1)[:, None] for v in n]
    best = np.full(len(p), 180.)
    for i in range(4):
        for j in range(i + 1, 4):
            # the interior angle at the edge shared by faces i and j, from their outward normals
            cos = np.clip(-np.einsum('ij,ij->i', n[i], n[j]), -1., 1.)
            best = np.minimum(best, np.degrees(np.arccos(cos)))
    return best


def check_mesh(path):
    """Problems found in a Medit mesh (empty: valid), and its smallest dihedral angle."""
    m = meshio.read(path)
    tets = np.concatenate([np.asarray(b.data) for b in m.cells if b.type == 'tetra']) if any(
        b.type == 'tetra' for b in m.cells) else np.zeros((0, 4), dtype=np.int64)
    if len(tets) == 0:
        return ['no tetrahedron'], 0.
    pts = np.asarray(m.points, dtype=float)
    p = pts[tets]
    problems = []
    volume = np.einsum('ij,ij->i', np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    if np.any(volume <= 0):
        problems.append('%d tetrahedra not positive' % np.count_nonzero(volume <= 0))
    faces = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 3, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 1]]])
    key = np.sort(faces, axis=1)
    _, index, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    index = index.reshape(-1)
    if np.any(counts > 2):
        problems.append('%d triangles in more than two tetrahedra' % np.count_nonzero(counts > 2))
    boundary = faces[counts[index] == 1]
    directed = np.concatenate([boundary[:, [0, 1]], boundary[:, [1, 2]], boundary[:, [2, 0]]])
    undirected = np.sort(directed, axis=1)
    _, ucount = np.unique(undirected, axis=0, return_counts=True)
    _, dcount = np.unique(directed, axis=0, return_counts=True)
    if np.any(ucount != 2) or np.any(dcount != 1):
        problems.append('boundary not a closed oriented manifold (%d edges not in two boundary triangles, '
                        '%d directed edges repeated)' % (np.count_nonzero(ucount != 2), np.count_nonzero(dcount != 1)))
    return problems, float(dihedral_min(p).min())


def run_model(args, model):
    name = os.path.basename(model)   # whole name: sphere.off, .ply and .stl run in different shards
    out_mesh = os.path.join(args.out, name + '.mesh')
    out_stats = os.path.join(args.out, name + '.json')
    for f in (out_mesh, out_stats):
        if os.path.exists(f):
            os.remove(f)
    cmd = [args.lattice_mesh, model, '--vertices', str(args.vertices), '--threads', '1', '--quiet',
           '-o', out_mesh, '--stats', out_stats] + args.option
    start = time.time()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        rc, err = proc.returncode, proc.stderr
    except subprocess.TimeoutExpired:
        rc, err = None, ''
    seconds = time.time() - start
    row = {'model': os.path.basename(model), 'seconds': round(seconds, 2), 'vertices': '', 'theta_min': '',
           'hausdorff_over_l': '', 'hausdorff_over_h': '', 'warnings': err.count('warning:')}
    closed = is_closed(model)
    if rc is None:
        row.update(outcome='fail', detail='no answer within %d s' % args.timeout)
    elif rc < 0:
        row.update(outcome='fail', detail='crashed (%s)' % signal.Signals(-rc).name)
    elif rc == 1:
        message = [l for l in err.splitlines() if 'error:' in l]
        message = message[0].split('error:', 1)[1].strip() if message else ''
        if closed:
            row.update(outcome='fail', detail='closed input refused: ' + (message or err.strip()[-200:]))
        elif message:
            row.update(outcome='refused', detail=message)
        else:
            row.update(outcome='fail', detail='refused without a message')
    elif rc == 0 or rc == 2:
        if not closed:
            row.update(outcome='fail', detail='open input meshed without an error')
            return row
        problems, smallest = check_mesh(out_mesh)
        stats = json.load(open(out_stats))
        row.update(vertices=stats['vertices'], theta_min=round(smallest, 2),
                   hausdorff_over_l=round(stats['hausdorff'] / stats['edge_length'], 3),
                   hausdorff_over_h=round(stats['hausdorff_over_size'], 3))
        if smallest < args.min_angle:
            problems.append('smallest dihedral angle %.2f < %g' % (smallest, args.min_angle))
        if stats['hausdorff'] > args.hausdorff * stats['edge_length']:
            problems.append('Hausdorff %.4g > %g l* (l* = %.4g)' % (stats['hausdorff'], args.hausdorff, stats['edge_length']))
        if not 0 <= stats['hausdorff_over_size'] <= args.hausdorff:
            problems.append('Hausdorff %.3g times the local size > %g' % (stats['hausdorff_over_size'], args.hausdorff))
        warned = 'the mesh lacks a part' in err or "the mesh's boundary at" in err
        if warned != (stats['hausdorff_over_size'] > 1.5):
            problems.append('the warning of a part lost %s (Hausdorff %.3g times the local size)' % (
                'given' if warned else 'not given', stats['hausdorff_over_size']))
        if rc == 2:
            problems.append('lattice-mesh reported an invalid mesh')
        row.update(outcome='fail' if problems else 'valid', detail='; '.join(problems))
    else:
        row.update(outcome='fail', detail='exit status %d: %s' % (rc, err.strip()[-200:]))
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--lattice-mesh', required=True)
    ap.add_argument('--models', required=True, help='folder of surface files')
    ap.add_argument('--vertices', type=int, default=3000)
    ap.add_argument('--shard', default='0/1', help='I/N: every N-th model from the I-th')
    ap.add_argument('--out', default='sweep-out')
    ap.add_argument('--csv', help='write the rows here')
    ap.add_argument('--timeout', type=int, default=900)
    ap.add_argument('--min-angle', type=float, default=10.)
    ap.add_argument('--hausdorff', type=float, default=1.5,
                    help='largest Hausdorff distance, in l* and in the local size (the longest edge near each sample)')
    ap.add_argument('--known-failures', help='file of "model: reason" lines')
    ap.add_argument('--only', help='comma-separated model files to mesh (default: all)')
    ap.add_argument('--option', action='append', default=[], help='a further lattice-mesh argument (repeat)')
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    i, n = (int(x) for x in args.shard.split('/'))
    models = sorted(f for f in os.listdir(args.models) if f.rsplit('.', 1)[-1].lower() in ('off', 'obj', 'stl', 'ply'))
    if args.only:
        models = [m for m in models if m in args.only.split(',')]
    models = models[i::n]
    known = {}
    if args.known_failures:
        for line in open(args.known_failures):
            line = line.split('#', 1)[0].strip()
            if line:
                model, reason = line.split(':', 1)
                known[model.strip()] = reason.strip()
    rows = []
    for model in models:
        row = run_model(args, os.path.join(args.models, model))
        rows.append(row)
        print('%-32s %-8s %8s V  theta_min %6s  H/l* %6s  H/h %6s  %7.2f s  %s' % (
            row['model'], row['outcome'], row['vertices'], row['theta_min'], row['hausdorff_over_l'],
            row['hausdorff_over_h'], row['seconds'], row['detail']), flush=True)
    if args.csv:
        with open(args.csv, 'w', newline='') as f:
            w = csv.DictWriter(f, fieldnames=['model', 'outcome', 'vertices', 'theta_min', 'hausdorff_over_l',
                                              'hausdorff_over_h', 'seconds', 'warnings', 'detail'])
            w.writeheader()
            w.writerows(rows)
    # a listed model may fail the check against the local size only: valid, its smallest angle and
    # its Hausdorff distance over l* within the thresholds, warned of
    def excused(r):
        return r['model'] in known and r['outcome'] == 'fail' and r['vertices'] != '' and \
            all(p.startswith('Hausdorff ') and p.endswith('times the local size > %g' % args.hausdorff)
                for p in r['detail'].split('; '))
    failed = [r for r in rows if r['outcome'] == 'fail' and not excused(r)]
    expected = [r for r in rows if excused(r)]
    fixed = [r['model'] for r in rows if r['outcome'] != 'fail' and r['model'] in known]
    counts = {k: sum(r['outcome'] == k for r in rows) for k in ('valid', 'refused', 'fail')}
    print('\n%d models: %d valid, %d refused (open or unreadable), %d failed (%d known), %.0f s' % (
        len(rows), counts['valid'], counts['refused'], counts['fail'], len(expected),
        sum(r['seconds'] for r in rows)))
    if fixed:
        print('known failures that now pass (remove them from the list): ' + ', '.join(fixed))
    for r in failed:
        print('FAILED: %s: %s' % (r['model'], r['detail']))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
