"""docs/AUTOMATIC.md's picture (the README's first until the gallery): VTK's vtkShadowMapPass, the old default (depth maps in
cascades) and the automatic pass on the same bench set-ups, each as the bench's error
map against ray-cast truth (grey where it agrees, red where light leaks into a true
shadow, blue where it draws a false shadow), captioned with its misclassified %.

  python3 Measurement/readme_picture.py build/bin/vtkshadows docs/images/readme-comparison.png

Runs `vtkshadows bench` once per row (a scene and a set-up, under xvfb-run unless a
display is set) into $TMPDIR/readme-picture-bench and composes the error maps, each
halved, with Pillow (python3-pil).
"""
import csv
import os
import subprocess
import sys

from PIL import Image, ImageDraw

ROWS = [("model", "facing", "a model, the sun facing the viewer"),
        ("outdoor", "street-point", "a street of boxes, a lamp among them")]
COLUMNS = [("vtk", "VTK's vtkShadowMapPass"),
           ("csm", "old default: depth maps, 4 cascades"),
           ("auto", "this module's default: automatic")]
CAPTION = 34
LEGEND = ("grey: as the ray-cast truth (dark in shadow); red: light where the truth is "
          "shadow; blue: shadow where the truth is lit")


def bench(vtkshadows, scene, setup, out):
    command = [vtkshadows, "bench", "--scenes", scene, "--setups", setup,
               "--techniques", "csm,auto", "--flicker-frames", "0",
               "--timed-frames", "1", "--out", out]
    if not os.environ.get("DISPLAY"):
        command = ["xvfb-run", "-a", "-s", "-noreset -screen 0 1280x1024x24"] + command
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "results.csv")) as f:
        return {row["technique"]: float(row["misclassified"]) for row in csv.DictReader(f)}


def main(vtkshadows, output):
    scratch = os.path.join(os.environ.get("TMPDIR", "/tmp"), "readme-picture-bench")
    tiles = []
    for scene, setup, title in ROWS:
        out = os.path.join(scratch, f"{scene}-{setup}")
        misclassified = bench(vtkshadows, scene, setup, out)
        row = []
        for technique, name in COLUMNS:
            image = Image.open(os.path.join(out, f"{scene}-{setup}-{technique}-errors.png"))
            image = image.convert("RGB").resize((image.width // 2, image.height // 2),
                                                Image.LANCZOS)
            row.append((image, f"{name}\n{title}: {misclassified[technique]:.2f} % wrong"))
            print(f"{scene} {setup} {technique}: {misclassified[technique]:.3f} %")
        tiles.append(row)
    width, height = tiles[0][0][0].size
    sheet = Image.new("RGB", (width * len(COLUMNS), (height + CAPTION) * len(ROWS) + CAPTION // 2),
                      "white")
    draw = ImageDraw.Draw(sheet)
    for r, row in enumerate(tiles):
        for c, (image, caption) in enumerate(row):
            x, y = c * width, r * (height + CAPTION)
            sheet.paste(image, (x, y + CAPTION))
            draw.multiline_text((x + 6, y + 3), caption, fill="black")
    draw.text((6, sheet.height - CAPTION // 2 + 2), LEGEND, fill="black")
    sheet.save(output, optimize=True)
    print(output)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
