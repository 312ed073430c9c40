#!/usr/bin/env python3
"""Every TOML example in the documentation runs: each ```toml block of a tracked Markdown file
(results/ left out) is checked as a newcomer would use it.

  [experiment] ...      an experiment: written into a configs/experiments/ folder beside the
                        checkout's configs/scenes (so "../scenes/x.toml" resolves), `canopy plan`ned;
  [scene] ...           a scene file: ray-traced by `canopy reference` at 8x6 pixels (every copy
                        of every population too, which no single technique may render);
  [[object]], [[population]] fragments: added to a minimal scene, then ray-traced the same way;
  [camera_path] fragment: added to a minimal experiment, then planned.

Usage: test_doc_examples.py CANOPY CHECKOUT
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

canopy, checkout = sys.argv[1], Path(sys.argv[2]).resolve()
BLOCK = re.compile(r"^```toml\n(.*?)^```", re.M | re.S)
BASE_SCENE = """[scene]
name = "doc-base"
[camera]
position = [0, 3, 8]
target = [0, 0.5, 0]
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
"""


def experiment(scene_file, extra=""):
    return (f'[experiment]\nname = "doc-example"\nscenes = ["{scene_file}"]\nresolutions = [[64, 48]]\n'
            f'{extra}\n[[technique]]\nname = "shadow.hard"\n')


def markdown_files():
    listed = subprocess.run(["git", "-C", str(checkout), "ls-files", "*.md"], capture_output=True, text=True,
                            check=True, env={"GIT_OPTIONAL_LOCKS": "0", "PATH": "/usr/bin:/bin"}).stdout.split()
    return [checkout / f for f in listed if not f.startswith("results/")]


def main():
    work = Path(tempfile.mkdtemp())
    (work / "configs/experiments").mkdir(parents=True)
    (work / "configs/scenes").symlink_to(checkout / "configs/scenes")
    failures, planned = [], 0
    for md in markdown_files():
        text = md.read_text()
        for match in BLOCK.finditer(text):
            block = match.group(1)
            line = text[:match.start()].count("\n") + 1
            where = f"{md.relative_to(checkout)}:{line}"
            scene = None
            if re.search(r"^\[experiment\]", block, re.M):
                config = block
            elif re.search(r"^\[scene\]|^\[camera\]", block, re.M):
                scene = block
            elif re.search(r"^\[\[(object|population)\]\]", block, re.M):
                scene = BASE_SCENE + "\n" + block
            elif re.search(r"^\[camera_path\]", block, re.M):
                config = experiment(checkout / "configs/scenes/spheres.toml") + "\n" + block
            else:
                failures.append(f"{where}: a TOML example this test does not know how to run; teach it")
                continue
            planned += 1
            if scene is not None:
                file = work / f"doc-scene-{planned}.toml"
                file.write_text(scene)
                command = [canopy, "reference", str(file), "--width", "8", "--height", "6", "--light-samples", "1",
                           "--pixel-samples", "1", "--no-cache", "--out", str(work / f"reference-{planned}")]
            else:
                file = work / "configs/experiments" / f"doc-example-{planned}.toml"
                file.write_text(config)
                command = [canopy, "plan", str(file)]
            result = subprocess.run(command, capture_output=True, text=True)
            if result.returncode != 0:
                failures.append(f"{where}: `canopy {command[1]}` of this example exits {result.returncode}:\n"
                                f"{result.stderr.strip()}")
    for failure in failures:
        print("FAIL:", failure)
    if planned == 0:
        print("FAIL: no TOML example found in the documentation")
        return 1
    print(f"doc examples: {planned} checked, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
