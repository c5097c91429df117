#!/usr/bin/env python3
"""Soak test of `vkwater view`: runs the viewer for many frames under a virtual X server, with
screenshots and scene changes along the way (or with window resizes), and fails when the memory the
process holds in use keeps growing after warm-up.

    python3 tests/soak/soak_view.py --vkwater build/tools/vkwater/vkwater [--frames 10000]
        [--validation] [--resizes 1000] [--max-growth-kib 1024]

The scene is pool, made light enough for thousands of frames on a CPU device (a 64-cell photon
grid, no godrays) at 160x120. The script's commands: a screenshot every 100 frames, a scene change
(`set`, which reloads the scene) every 50 frames, the water's clock set every 70 frames, a camera
glide every 200 frames; with --resizes N, instead a resize every 2 frames between 160x120 and
192x144, N in all. Every 10 frames the script's `heap` command prints the bytes the C heap holds in
use (all threads' arenas, the driver's included); the growth is the slope of a least-squares line
through those after the first 20% of the run (warm-up: pipelines compiled, caches filled), per
1,000 frames (or resizes). Exit 0 when that is under --max-growth-kib, 1 when not, 2 when the
viewer fails.

Why the heap and not the resident set: glibc keeps freed memory resident and gives each of
llvmpipe's threads an arena of its own, so the resident set rises by a few MiB as those arenas
reach their high-water marks and levels off (1.7 MiB per 1,000 frames over the first 1,500 frames,
0.5 over 4,500), while a real leak of 2 KiB per frame fills the holes freed memory left and does not
show in it at all. The bytes in use see such a leak from its first frame. The resident set is still
printed, for the record.
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent


def write_script(path, frames, resizes, shots):
    lines = []
    if resizes:
        for i in range(resizes):
            size = "192 144" if i % 2 == 0 else "160 120"
            lines.append(f"{2 * i + 1}: resize {size}")
    else:
        amplitudes = ["0.017", "0.012"]
        for frame in range(0, frames, 50):
            lines.append(f"{frame}: set water.waves.components[0].amplitude={amplitudes[(frame // 50) % 2]}")
        for frame in range(10, frames, 70):
            lines.append(f"{frame}: time {frame * 0.01:.2f}")
        for frame in range(20, frames, 200):
            target = "0 -1.5 -2" if (frame // 200) % 2 == 0 else "0.5 -1.5 -2"
            lines.append(f"{frame}: move 0 1.2 4 {target} 50")
        for frame in range(99, frames, 100):
            lines.append(f"{frame}: screenshot {shots}/shot-{frame % 300}.exr")  # a few names, rewritten
    for frame in range(0, frames, 10):
        lines.append(f"{frame}: heap")
    lines.sort(key=lambda line: int(line.split(":")[0]))
    path.write_text("\n".join(lines) + "\n")


def find_viewer(marker):
    """The pid of the vkwater process whose command line holds `marker` (xvfb-run starts it)."""
    for entry in pathlib.Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            cmdline = (entry / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if cmdline and cmdline[0].endswith(b"vkwater") and marker.encode() in b" ".join(cmdline):
            return int(entry.name)
    return None


def rss_kib(pid):
    try:
        for line in pathlib.Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    except OSError:
        return None
    return None


def slope(samples):
    n = len(samples)
    mean_t = sum(t for t, _ in samples) / n
    mean_m = sum(m for _, m in samples) / n
    var = sum((t - mean_t) ** 2 for t, _ in samples)
    return sum((t - mean_t) * (m - mean_m) for t, m in samples) / var if var > 0 else 0.0


def heap_samples(output):
    """(frame, bytes in use) from the viewer's `heap` lines: "heap: frame F, B bytes in use"."""
    samples = []
    for line in output.splitlines():
        match = re.fullmatch(r"heap: frame (\d+), (\d+) bytes in use", line.strip())
        if match:
            samples.append((int(match.group(1)), int(match.group(2)) / 1024.0))
    return samples


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--vkwater", required=True)
    parser.add_argument("--frames", type=int, default=10000)
    parser.add_argument("--resizes", type=int, default=0)
    parser.add_argument("--validation", action="store_true")
    parser.add_argument("--max-growth-kib", type=float, default=1024.0,
                        help="largest accepted growth per 1,000 frames (or resizes), KiB")
    args = parser.parse_args()

    frames = 2 * args.resizes + 10 if args.resizes else args.frames
    with tempfile.TemporaryDirectory(prefix="vkwater_soak_") as work:
        work = pathlib.Path(work)
        script = work / "soak-script.txt"
        write_script(script, frames, args.resizes, work)
        command = ["xvfb-run", "-a", "-s", "-screen 0 640x480x24", args.vkwater, "view", str(ROOT / "scenes/pool.json"),
                   "--width", "160", "--height", "120", "--frames", str(frames), "--present", "immediate",
                   "--pass-timing-every", "0", "--script", str(script),
                   "--set", "water.grid_resolution=64", "--set", "effects.godrays.mode=off"]
        if args.validation:
            command.append("--validation")
        start = time.monotonic()
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        samples, pid = [], None
        while process.poll() is None:
            pid = pid or find_viewer(str(script))
            memory = rss_kib(pid) if pid else None
            if memory:
                samples.append((time.monotonic() - start, memory))
            time.sleep(0.2)
        output = process.stdout.read()
        seconds = time.monotonic() - start
    heap = heap_samples(output)
    if process.returncode != 0 or len(heap) < 10:
        print(output[-3000:])
        print(f"soak: the viewer exited {process.returncode} after {seconds:.0f} s ({len(heap)} heap samples)")
        return 2
    steady = heap[len(heap) // 5:]
    per_frame_kib = slope(steady)
    unit = "resizes" if args.resizes else "frames"
    frames_per_unit = 2 if args.resizes else 1  # a resize every 2 frames
    growth = per_frame_kib * frames_per_unit * 1000.0
    verdict = "flat" if growth < args.max_growth_kib else "GROWING"
    resident = ""
    if len(samples) >= 10:
        # The resident set's growth after the same warm-up, per 1,000 frames (or resizes) assuming a
        # steady frame rate: printed for the record, not judged (see above).
        resident_steady = samples[len(samples) // 5:]
        resident_growth = (slope(resident_steady) * (resident_steady[-1][0] - resident_steady[0][0]) /
                           (heap[-1][0] * 0.8 / frames_per_unit) * 1000.0)
        resident = (f"; resident set {samples[0][1] / 1024:.0f} MiB at start, {samples[-1][1] / 1024:.0f} MiB at "
                    f"the end, {resident_growth:.0f} KiB per 1,000 {unit} after warm-up")
    print(f"soak: {frames} frames{' with validation' if args.validation else ''}"
          f"{f', {args.resizes} resizes' if args.resizes else ''} in {seconds:.0f} s; heap in use "
          f"{heap[0][1] / 1024:.1f} MiB at frame 0, {steady[0][1] / 1024:.1f} MiB after warm-up, "
          f"{heap[-1][1] / 1024:.1f} MiB at the end; growth after warm-up {growth:.0f} KiB per 1,000 {unit} "
          f"(accepted: under {args.max_growth_kib:.0f}){resident}: {verdict}")
    return 0 if growth < args.max_growth_kib else 1


if __name__ == "__main__":
    sys.exit(main())
