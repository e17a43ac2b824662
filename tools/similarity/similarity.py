#!/usr/bin/env python3
"""The detector behind `raylab similarity` (run by it; not for direct use).

Runs copydetect (PyPI; winnowed fingerprints of the token stream, names
replaced by placeholders, comments and layout dropped) on what `raylab
similarity` prepared in WORK:

    WORK/<stage>/base/handed-out.glsl     the code the lab hands out (boilerplate:
                                          matches inside it never count)
    WORK/<stage>/students/<student>.glsl  each student's own files of the stage

and writes into OUT:

    pairs.csv         every pair of every stage: stage, student_a, student_b,
                      similarity_a, similarity_b (the share of each one's own
                      tokens found in the other), flagged (1 when the larger
                      share reaches THRESHOLD)
    <stage>.html      copydetect's report of the stage: the flagged pairs side
                      by side, the shared code highlighted

Exit 0 with the number of flagged pairs on stdout's last line; exit 2 with
one line on stderr when copydetect is missing or WORK is not as above.
"""
import argparse
import csv
import logging
import sys
from pathlib import Path


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--work", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--threshold", type=float, required=True)
    args = parser.parse_args()
    try:
        import copydetect  # noqa: F401  (only to say clearly when it is missing)
        from copydetect import CopyDetector
    except ImportError:
        print("copydetect is not installed (bash install.sh sets up tools/similarity/.venv)",
              file=sys.stderr)
        return 2
    logging.disable(logging.WARNING)  # copydetect logs "no files" as errors; we say it ourselves

    work, out = Path(args.work), Path(args.out)
    rows = []
    for stage_dir in sorted(p for p in work.iterdir() if p.is_dir()):
        students = sorted((stage_dir / "students").glob("*.glsl"))
        if len(students) < 2:
            continue  # nothing to compare
        detector = CopyDetector(
            test_dirs=[str(stage_dir / "students")],
            ref_dirs=[str(stage_dir / "students")],
            boilerplate_dirs=[str(stage_dir / "base")],
            extensions=["glsl"],
            force_language="glsl",
            display_t=args.threshold,
            autoopen=False,
            silent=True,
            out_file=str(out / f"{stage_dir.name}.html"),
        )
        detector.run()
        matrix = detector.similarity_matrix
        names = [Path(f).stem for f in detector.test_files]
        for i in range(len(names)):
            for j in range(i + 1, len(names)):
                a, b = float(matrix[i, j, 0]), float(matrix[i, j, 1])
                first, second = names[i], names[j]
                if second < first:  # each pair in name order, its scores with it
                    first, second, a, b = second, first, b, a
                rows.append([stage_dir.name, first, second, f"{a:.3f}", f"{b:.3f}",
                             int(max(a, b) >= args.threshold)])
        detector.generate_html_report()
    rows.sort(key=lambda r: (r[0], -max(float(r[3]), float(r[4]))))
    with open(out / "pairs.csv", "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["stage", "student_a", "student_b", "similarity_a", "similarity_b",
                         "flagged"])
        writer.writerows(rows)
    print(sum(r[5] for r in rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
