#!/usr/bin/env python3
"""The agreement test's output -> dart_agreement.csv.

Usage: gq_dart_tests --gtest_filter=DartAgreement.* > out.txt; dart_agreement.to_csv.py out.txt [--out CSV]
One row per scene where DART's fcl or bullet detector answers collide differently from the exact answer (the
closed-form signed distance for pairs with a sphere; for the others a long-double brute force: the distance when
apart, 0 for an overlap of at least 1e-9) and gq's signed distance (minus the depth), and one summary row, with the run's date, machine and commit.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "detector", "scene", "pair", "detector_collides", "reference",
          "reference_distance", "gq_signed_distance", "note"]
COMMENTS = ["# DartAgreement.ThousandRandomScenesAgainstFclBulletAndExact (tests/dart/agreement_test.cpp): 1000 seeded"
            " two-shape scenes; rows: each disagreement of fcl or bullet with the reference; last row: the totals."]
LINE = re.compile(r"^(fcl|bullet) disagrees: scene (\d+) (\S+) \w+ (\d), (exact) distance (\S+), gq signed distance (\S+)$")
SUMMARY = re.compile(r"^scenes (\d+) \(colliding (\d+), .*\): fcl wrong (\d+), bullet wrong (\d+), .* exact distance (\S+)$")


def main():
    args = results_csv.script_args("dart_agreement.csv", inputs="output", nargs=None, machine=False)
    cols = results_csv.run_columns()
    rows = []
    with open(args.output) as f:
        for line in f:
            line = line.strip()
            m = LINE.match(line)
            if m:
                detector, scene, pair, answer, ref, value, signed = m.groups()
                note = ""
                if detector == "fcl" and "capsule" in pair:
                    note = "DART's fcl detector models a capsule as a sphere of radius 0.1 (its error log says so)"
                elif detector == "fcl" and float(value) <= 0:
                    note = "fcl's primitives are meshes: containment or shallow overlap without crossing triangles"
                elif detector == "bullet" and float(value) > 0:
                    note = "within Bullet's collision margin"
                elif detector == "bullet":
                    note = "shallow overlap missed"
                rows.append(dict(cols, detector=detector, scene=scene, pair=pair, detector_collides=answer,
                                 reference=ref, reference_distance=value, gq_signed_distance=signed, note=note))
            m = SUMMARY.match(line)
            if m:
                total, colliding, fcl, bullet, err = m.groups()
                rows.append(dict(cols, detector="summary", scene=total, pair="all", detector_collides=colliding,
                                 reference="exact", reference_distance="",
                                 note="fcl wrong %s, bullet wrong %s, gq wrong 0; gq distance max error against the"
                                      " exact distance %s" % (fcl, bullet, err)))
    results_csv.write(args.out, HEADER, rows, comments=COMMENTS)


if __name__ == "__main__":
    main()
