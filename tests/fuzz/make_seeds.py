#!/usr/bin/env python3
"""Writes the seed inputs of the fuzz targets into <out>/<target>/ (deterministic; rerun to regenerate).

Seeds are small valid inputs of each format plus a few broken ones; the query targets get seeded random bytes
(fuzz_decode.h reads any byte string). The committed corpora, tests/fuzz/corpus/<target>.tar.gz, are not written
here: they are the seeds plus the inputs long fuzz runs grew, minimised with libFuzzer's -merge=1 (the smallest set
of inputs that keeps every coverage feature, named by content hash), one archive per target, under 5 MB in all. To
bring seeds in, or to minimise a corpus again (ASan+UBSan build as scripts/sanitize makes it, ASAN_OPTIONS and the
gq_*_corpus functions from scripts/sanitizer-env):

    tests/fuzz/make_seeds.py /tmp/seeds
    . scripts/sanitizer-env && gq_unpack_corpus fuzz_urdf /tmp/old/fuzz_urdf
    build-asan/tests/fuzz/fuzz_urdf -merge=1 /tmp/min/fuzz_urdf /tmp/old/fuzz_urdf /tmp/seeds/fuzz_urdf
    gq_pack_corpus fuzz_urdf /tmp/min/fuzz_urdf
"""
import argparse
import json
import os
import random
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
OUT = None  # the output folder, set by main()


def write(target, name, data):
    folder = os.path.join(OUT, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def case_file_seeds():
    n = 0
    examples = os.path.join(ROOT, "comparisons", "cases", "examples")
    for name in sorted(os.listdir(examples)):
        if not name.endswith(".jsonl"):
            continue
        for line in open(os.path.join(examples, name)):
            if line.strip() and "file" not in line:
                write("fuzz_case_file", "example_%02d.jsonl" % n, line)
                n += 1
    pose = {"p": [0.5, -0.25, 0], "q": [0, 0, 0.38268343, 0.92387953]}
    extra = [
        {"id": "hf", "query": "raycast", "geom": {"type": "heightfield", "rows": 3, "columns": 3,
                                                  "heights": [0, 1, 0, 1, 2, 1, 0, 1, 0], "rowScale": 1,
                                                  "columnScale": 1, "heightScale": 1, "holes": [1]},
         "origin": [0.5, 5, 0.5], "dir": [0, -1, 0], "maxDist": 10, "flags": ["position", "normal", "uv"]},
        {"id": "mesh", "query": "distance", "geom0": {"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0],
                                                                                  [0, 0, 1]],
                                                      "triangles": [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]},
         "pose0": pose, "geom1": {"type": "cylinder", "radius": 0.5, "halfHeight": 1}, "pose1": pose},
        {"id": "convex", "precision": "float", "query": "sweep",
         "geom0": {"type": "convex", "points": [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                   "scale": {"s": [1, 2, 0.5], "q": [0, 0, 0, 1]}},
         "pose0": pose, "dir": [0, 0, 1], "maxDist": 5, "geom1": {"type": "cone", "radius": 1, "halfHeight": 1},
         "pose1": {"p": [0, 0, 3], "q": [0, 0, 0, 1]}, "flags": ["position", "normal", "mtd"], "inflation": 0.1},
        {"id": "extreme", "query": "penetration", "geom0": {"type": "box", "halfExtents": [1e-30, 1e30, 1]},
         "geom1": {"type": "capsule", "radius": 1e-6, "halfHeight": 1e6}},
    ]
    for i, case in enumerate(extra):
        write("fuzz_case_file", "extra_%02d.jsonl" % i, json.dumps(case) + "\n")


def mesh_file_seeds():
    obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
    quad_obj = "o q\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n"
    ascii_stl = ("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                 "endfacet\nendsolid t\n")
    tri = struct.pack("<12f", 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\0\0"
    binary_stl = b" " * 80 + struct.pack("<I", 2) + tri + tri
    concave_obj = ("v 4 0 0\nv 1 1 0\nv 0 4 0\nv 0 0 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3//1 4\n"
                   "v 0 0 1\nf -1 -2 -3\nl 1 2\n")
    # First byte: even = .obj, odd = .stl. DAE is not mutated (assimp's Collada loader
    # segfaults on malformed files: known_crashes/); tests/core covers DAE loading.
    seeds = {"tetra.obj": b"\0" + obj.encode(), "quad.obj": b"\0" + quad_obj.encode(),
             "concave.obj": b"\0" + concave_obj.encode(),
             "bad_index.obj": b"\0" + b"v 0 0 0\nv 1 0 0\nf 1 2 7\n", "ascii.stl": b"\1" + ascii_stl.encode(),
             "binary.stl": b"\1" + binary_stl, "binary_truncated.stl": b"\1" + binary_stl[:120],
             "empty.obj": b"\0"}
    for name, data in seeds.items():
        write("fuzz_mesh_file", name, data)
        if name.endswith(".stl"):
            write("fuzz_mesh_file_stl", name, data)  # the STL-only build (every input saved as .stl)


def urdf_seeds():
    def robot(collision_b, joint="revolute", extra=""):
        return ('<robot name="r"><link name="a"><collision><geometry><box size="1 1 1"/></geometry></collision></link>'
                '<link name="b"><collision><origin xyz="0 0 0.5" rpy="0.1 0 0"/><geometry>%s</geometry></collision>'
                '</link><joint name="j" type="%s"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
                '<origin xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>%s</robot>'
                % (collision_b, joint, extra))
    srdf = ('<robot name="r"><group name="arm"><joint name="j"/></group><group_state name="home" group="arm">'
            '<joint name="j" value="0.5"/></group_state><disable_collisions link1="a" link2="b" reason="Adjacent"/>'
            '</robot>')
    mimic = ('<link name="c"><collision><geometry><sphere radius="0.2"/></geometry></collision></link>'
             '<joint name="k" type="prismatic"><parent link="b"/><child link="c"/><axis xyz="1 0 0"/>'
             '<mimic joint="j" multiplier="2" offset="0.1"/>'
             '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')
    seeds = [
        (1, robot('<sphere radius="0.5"/>'), None),
        (1, robot('<cylinder radius="0.3" length="1"/>', "continuous"), srdf),
        (0, robot('<mesh filename="cube.stl" scale="1 2 -1"/>'), None),
        (1, robot('<mesh filename="package://cube.stl"/>', "fixed"), None),
        (6, robot('<mesh filename="cube.stl"/>', "revolute", mimic), srdf),
        (2, robot('<box size="0.2 0.3 0.4"/>', "prismatic"), srdf),
        (3, robot('<sphere radius="nan"/>'), None),
        (4, robot('<box size="1 0 1"/>'), "<robot><disable_collisions link1=\"a\"/></robot>"),
        (5, '<robot name="r"><link name="a"/>', None),
    ]
    for i, (rep, urdf, s) in enumerate(seeds):
        data = bytes([rep]) + urdf.encode() + ((b"\0" + s.encode()) if s is not None else b"")
        write("fuzz_urdf", "robot_%02d.bin" % i, data)


def random_seeds(target, count, rng):
    for i in range(count):
        write(target, "random_%02d.bin" % i, bytes(rng.randrange(256) for _ in range(rng.choice([32, 96, 256, 512]))))


def main():
    global OUT
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("out", help="folder to write the <target>/ seed folders into (not tests/fuzz/corpus)")
    OUT = os.path.abspath(parser.parse_args().out)
    if OUT == os.path.join(HERE, "corpus"):
        parser.error("the committed corpora are minimised: write the seeds elsewhere and -merge=1 them in")
    rng = random.Random(9)
    case_file_seeds()
    mesh_file_seeds()
    urdf_seeds()
    for target in ("fuzz_raycast", "fuzz_pair_queries", "fuzz_point_queries", "fuzz_mesh_queries"):
        random_seeds(target, 16, rng)
    return 0


if __name__ == "__main__":
    sys.exit(main())
