#!/usr/bin/env python3
"""How busy llvmpipe's lock-step lanes are in each turn of the trace loop.

  python3 tools/bench/lane_occupancy.py BOUNCES.pfm

BOUNCES.pfm: rays per pixel, from the reference tracer's bounces view, e.g.
  build/raylab render --stage 08 --solution --scene pro --reference \\
      --view bounces --out bounces.pfm

llvmpipe shades 8 pixels at once and runs a turn of the trace loop for all
8 while any of them still has a ray. For blocks of 4 x 2 and of 2 x 4 pixels
this prints, per turn, how many blocks run it and what share of their lanes
have a ray of their own there (the rest run masked), and that share over all
turns. A renderer that packs live rays together between passes could save
at most the idle share. Used for docs/bench/README.md ("Issue 47").
"""
import struct
import sys


def read_pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        if kind != b'Pf':
            raise ValueError(f'{path}: not a one-channel PFM (starts with {kind!r}, not Pf)')
        width, height = (int(v) for v in f.readline().split())
        scale = float(f.readline())
        data = f.read(4 * width * height)
    if len(data) != 4 * width * height:
        raise ValueError(f'{path}: {len(data) // 4} values for {width}x{height} pixels')
    order = '<' if scale < 0 else '>'
    values = struct.unpack(f'{order}{width * height}f', data)
    return width, height, [int(round(v)) for v in values]


def blocks(width, height, rays, bw, bh):
    for y in range(0, height - bh + 1, bh):
        for x in range(0, width - bw + 1, bw):
            yield [rays[(y + j) * width + x + i] for j in range(bh) for i in range(bw)]


def main(argv):
    if len(argv) != 2 or argv[1] in ('-h', '--help'):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    try:
        width, height, rays = read_pfm(argv[1])
    except (OSError, ValueError) as e:
        print(f'lane_occupancy.py: {e}', file=sys.stderr)
        return 1
    print(f'{argv[1]}: {width}x{height} pixels, {sum(rays)} rays, at most {max(rays)} a pixel')
    for bw, bh in ((4, 2), (2, 4)):
        groups = list(blocks(width, height, rays, bw, bh))
        if not groups:
            print(f'blocks of {bw} x {bh}: none in a {width}x{height} picture')
            continue
        lanes = bw * bh
        busy = sum(map(sum, groups))
        run = sum(max(g) for g in groups) * lanes
        print(f'blocks of {bw} x {bh}: {100.0 * busy / run:.1f}% of the lanes run busy over all turns')
        for turn in range(1, max(rays) + 1):
            live = sum(1 for g in groups for v in g if v >= turn)
            running = sum(1 for g in groups if max(g) >= turn)
            print(f'  turn {turn}: {running} blocks, {100.0 * live / (running * lanes):.1f}% of their lanes busy')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
