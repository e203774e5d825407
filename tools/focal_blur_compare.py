#!/usr/bin/env python3
"""Focal blur against POV-Ray: camera/focalblur.pov with many lens samples, both renders compared by their 8x8
block means (docs/povray-language.md, focal blur). Usage: focal_blur_compare.py BINARY [WIDTH HEIGHT]."""
import pathlib
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

SCENES = pathlib.Path("/usr/share/povray-3.7/scenes/camera")


def block_means(path, block=8):
    a = np.asarray(Image.open(path).convert("RGB")).astype(float)
    h, w = a.shape[0] // block * block, a.shape[1] // block * block
    return a[:h, :w].reshape(h // block, block, w // block, block, 3).mean((1, 3))


def main():
    binary = pathlib.Path(sys.argv[1]).resolve()
    width, height = (sys.argv[2], sys.argv[3]) if len(sys.argv) > 3 else ("160", "120")
    with tempfile.TemporaryDirectory() as folder:
        work = pathlib.Path(folder)
        for inc in SCENES.glob("*.inc"):
            shutil.copy(inc, work)
        text = (SCENES / "focalblur.pov").read_text()
        text = text.replace("blur_samples 120", "blur_samples 7, 400 variance 1/20000")
        (work / "fb.pov").write_text(text)
        subprocess.run(["povray", "+Ifb.pov", f"+W{width}", f"+H{height}", "-A", "+Opov.png", "-D"], cwd=work,
                       check=True, capture_output=True)
        subprocess.run([str(binary), "render", "fb.pov", width, height, "-o", "rt.png"], cwd=work, check=True,
                       capture_output=True)
        diff = np.abs(block_means(work / "pov.png") - block_means(work / "rt.png")).max(2)
        print(f"8x8 block means: largest difference {diff.max():.2f}/255, mean {diff.mean():.2f}/255")
        return 0 if diff.max() <= 4 else 1


if __name__ == "__main__":
    sys.exit(main())
