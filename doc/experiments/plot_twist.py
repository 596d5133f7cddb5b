#!/usr/bin/env python3
"""BFEMP Section 6.7, 3D twist with friction: Figure 17 and Figure 16-like renders.

    /usr/bin/python3 doc/experiments/plot_twist.py [OUTPUT_DIR] [PREFIX ...]
    xvfb-run -a /usr/bin/python3 doc/experiments/plot_twist.py [OUTPUT_DIR] [PREFIX ...]

OUTPUT_DIR (default `output`) holds the run folders <PREFIX>_mu0, <PREFIX>_mu0_2,
<PREFIX>_mu0_5, <PREFIX>_mu1_0 written by the prm files of prm/experiments/6_7_twist/
(PREFIX default `twist`; `twist_reduced` and `twist_medium` for the coarser runs).
Missing runs are skipped; a run still going is read up to its last snapshot.

Twist angle of the cube's top: the particles of the topmost particle layer of the
cube (rest z within 1e-6 of the largest rest z) whose rest distance from the z axis is
below 0.25 m ("top center of the cube", as the paper plots); for each, the rotation
angle about the z axis from its rest position (the VTU's displacement field gives the
rest position), unwrapped in time; the mean over them. The shell's angle is the
prescribed one, pi/5 (t - 1 s) for 1 s <= t <= 5.5 s (the prm files' time line).

Writes doc/images/experiments/twist_angle.png (cube-top angle and shell angle vs
time per mu, as Figure 17), twist_slip.png (slip = shell angle - cube-top angle vs
shell angle), twist_snapshots.png (needs VTK offscreen rendering: run under
xvfb-run -a; Debian packages python3-vtk9, python3-matplotlib, xvfb), and prints a
table of the slip onset per mu (the shell angle at which the cube's top first
turns at less than half the shell's angular velocity over 0.2 s). The figures of
PREFIX other than `twist` carry its suffix (twist_angle_reduced.png, ...). With
several PREFIXes, twist_resolution.png also compares their slip curves (colour:
mu, line style: PREFIX in the order given); `--compare` draws only that figure and
the tables, leaving each PREFIX's own figures as they are.
"""
import math
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import vtk
from vtk.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_data import pvd, read_grid  # noqa: E402

IMAGES = os.path.join(HERE, "..", "images", "experiments")
MUS = [("0", 0.0), ("0_2", 0.2), ("0_5", 0.5), ("1_0", 1.0)]
OMEGA = math.pi / 5.
T_TWIST, T_END = 1.0, 5.5
TOP_RADIUS = 0.25
VMAX = 1e8  # colour range of the particles' von Mises stress [Pa]


def shell_angle(t):
    return OMEGA * np.clip(np.asarray(t) - T_TWIST, 0., T_END - T_TWIST)


def series(folder, stem):
    """(time, file) of a .pvd series; empty if the run wrote none."""
    path = os.path.join(folder, stem + ".pvd")
    return pvd(path) if os.path.exists(path) else []


def twist_history(folder):
    """Times and mean twist angle of the top centre of the cube."""
    frames = series(folder, "particles")
    times, angles = [], []
    top, top_rest, previous, unwrapped = None, None, None, None
    for t, f in frames:
        g = read_grid(f)
        x = vtk_to_numpy(g.GetPoints().GetData()).astype(float)
        u = vtk_to_numpy(g.GetPointData().GetArray("displacement")).astype(float)
        x0 = x - u
        if top is None:
            zmax = x0[:, 2].max()
            r0 = np.hypot(x0[:, 0], x0[:, 1])
            top = np.where((x0[:, 2] > zmax - 1e-6) & (r0 < TOP_RADIUS))[0]
            top_rest = x0[top]
        # A point index must name the same particle in every snapshot (bfemp
        # writes particles in id order since commit fb4876a); before, the order
        # followed the cells, and the indices chosen above named other
        # particles once the cube had deformed.
        if not np.allclose(x0[top], top_rest, rtol=0., atol=1e-5):
            sys.exit(f"{f}: the top-centre particles' rest positions differ from the "
                     "first snapshot's: the VTU files do not list the particles in "
                     "the same order (written by a bfemp older than fb4876a?)")
        a = np.arctan2(x[top, 1], x[top, 0]) - np.arctan2(x0[top, 1], x0[top, 0])
        a = (a + np.pi) % (2 * np.pi) - np.pi
        if previous is None:
            unwrapped = a
        else:
            unwrapped = unwrapped + ((a - previous + np.pi) % (2 * np.pi) - np.pi)
        previous = a
        times.append(t)
        angles.append(unwrapped.mean())
    return np.array(times), np.array(angles), (0 if top is None else len(top))


def slip_onset(t, cube, window=0.2):
    """Shell angle at which the slip starts: the middle of the first time
    window (0.2 s, four snapshot intervals: shorter windows see the top's
    rocking of a few 0.01 rad) after the twist starts over which the cube
    top turns at less than half the shell's angular velocity; None if it
    never does."""
    for i in range(len(t)):
        j = int(np.searchsorted(t, t[i] + window - 1e-9))
        if j >= len(t) or t[i] < T_TWIST - 1e-9 or t[j] > T_END + 1e-9:
            continue
        if (cube[j] - cube[i]) / (t[j] - t[i]) < 0.5 * OMEGA:
            return float(shell_angle(0.5 * (t[i] + t[j])))
    return None


def render(folders, out):
    """One frame per mu at the end of the twist: cube particles and shell,
    coloured by von Mises stress (offscreen VTK)."""
    frames = []
    for label, folder in folders:
        p = series(folder, "particles")
        s = series(folder, "fem_body_0")
        if p and s:
            frames.append((label, p[-1], s[-1]))
    if not frames:
        return
    w, h = 360, 360
    tiles = []
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetTableRange(0., VMAX)
    lut.Build()
    for label, (tp, fp), (ts, fs) in frames:
        ren = vtk.vtkRenderer()
        ren.SetBackground(1, 1, 1)
        g = read_grid(fp)
        g.GetPointData().SetActiveScalars("von_mises")
        geom = vtk.vtkVertexGlyphFilter()
        geom.SetInputData(g)
        m = vtk.vtkPolyDataMapper()
        m.SetInputConnection(geom.GetOutputPort())
        m.SetLookupTable(lut)
        m.SetScalarRange(0., VMAX)
        m.SetScalarModeToUsePointData()
        a = vtk.vtkActor()
        a.SetMapper(m)
        a.GetProperty().SetPointSize(max(2., 14. * (512. / g.GetNumberOfPoints()) ** (1. / 3.)))
        a.GetProperty().SetRenderPointsAsSpheres(True)
        ren.AddActor(a)
        sh = read_grid(fs)
        sh.GetPointData().SetActiveScalars("von_mises")
        # only the half of the shell behind the axis, so the cube's top shows
        clip = vtk.vtkClipDataSet()
        clip.SetInputData(sh)
        plane = vtk.vtkPlane()
        plane.SetOrigin(0, 0, 0)
        plane.SetNormal(-1, 1, 0)
        clip.SetClipFunction(plane)
        surf = vtk.vtkDataSetSurfaceFilter()
        surf.SetInputConnection(clip.GetOutputPort())
        sm = vtk.vtkDataSetMapper()
        sm.SetInputConnection(surf.GetOutputPort())
        sm.ScalarVisibilityOff()
        sa = vtk.vtkActor()
        sa.SetMapper(sm)
        sa.GetProperty().SetColor(0.75, 0.75, 0.75)
        sa.GetProperty().SetOpacity(0.35)
        sa.GetProperty().EdgeVisibilityOn()
        sa.GetProperty().SetEdgeColor(0.3, 0.3, 0.3)
        ren.AddActor(sa)
        cam = ren.GetActiveCamera()
        cam.SetFocalPoint(0, 0, 0.75)
        cam.SetPosition(2.2, -2.2, 3.2)
        cam.SetViewUp(0, 0, 1)
        ren.ResetCameraClippingRange()
        cam.Zoom(1.25)
        rw = vtk.vtkRenderWindow()
        rw.SetOffScreenRendering(1)
        rw.AddRenderer(ren)
        rw.SetSize(w, h)
        rw.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(rw)
        grab.Update()
        img = grab.GetOutput()
        nx, ny, _ = img.GetDimensions()
        arr = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(ny, nx, -1)[::-1]
        tiles.append((label, tp, arr))
    fig, axes = plt.subplots(1, len(tiles), figsize=(3.2 * len(tiles), 3.4))
    axes = np.atleast_1d(axes)
    for ax, (label, t, arr) in zip(axes, tiles):
        ax.imshow(arr)
        ax.set_axis_off()
        ax.set_title(f"{label}, t = {t:.2f} s", fontsize=10)
    sm = plt.cm.ScalarMappable(cmap="jet", norm=plt.Normalize(0, VMAX))
    fig.colorbar(sm, ax=list(axes), shrink=0.7,
                 label="cube: von Mises [Pa]")
    fig.savefig(out, dpi=70, bbox_inches="tight")
    plt.close(fig)


def runs_of(root, prefix):
    """(mu, folder) of every run <prefix>_mu* in root that wrote particles."""
    runs = []
    for tag, mu in MUS:
        folder = os.path.join(root, f"{prefix}_mu{tag}")
        if os.path.exists(os.path.join(folder, "particles.pvd")):
            runs.append((mu, folder))
    return runs


def suffix_of(prefix):
    return "" if prefix == "twist" else "_" + prefix.replace("twist_", "")


def finish_slip_axes(bx, legend_size):
    """Labels of a slip vs shell angle panel, with the paper's onsets."""
    for onset, mu in ((0.1, 0), (0.3, 0.2), (0.7, 0.5)):
        bx.axvline(onset, color="grey", ls=":", lw=1)
        bx.text(onset, 0.02, f" paper onset\n mu = {mu:g}", fontsize=7, color="grey",
                transform=bx.get_xaxis_transform())
    bx.set_xlabel("shell twist angle [pi rad]")
    bx.set_ylabel("slip = shell angle - cube top angle [rad]")
    bx.legend(fontsize=legend_size)
    bx.grid(alpha=0.3)


def plot_prefix(prefix, histories, table_only=False):
    """Figure 17 (angle vs time) and slip vs shell angle for one PREFIX; with
    table_only just the printed table."""
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 3.8))
    tt = np.linspace(0, T_END, 200)
    ax.plot(tt, shell_angle(tt), "k--", label="shell (prescribed)")
    print(f"{prefix}:")
    print("| mu | particles in the top centre | cube top angle at the last snapshot [rad] |"
          " slip there [rad] | slip onset, shell angle [pi] |")
    print("|---|---|---|---|---|")
    for mu, (t, a, n) in histories:
        ax.plot(t, a, label=f"mu = {mu:g}")
        bx.plot(shell_angle(t) / math.pi, shell_angle(t) - a, label=f"mu = {mu:g}")
        onset = slip_onset(t, a)
        print(f"| {mu:g} | {n} | {a[-1]:.3f} (t = {t[-1]:.2f}) | "
              f"{shell_angle(t[-1]) - a[-1]:.3f} | "
              f"{'none' if onset is None else f'{onset / math.pi:.2f}'} |")
    if table_only:
        plt.close(fig)
        return
    ax.set_xlabel("time [s]")
    ax.set_ylabel("twist angle of the cube's top centre [rad]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    finish_slip_axes(bx, 8)
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, f"twist_angle{suffix_of(prefix)}.png"), dpi=80)
    plt.close(fig)


def plot_resolutions(histories_per_prefix):
    """Slip vs shell angle of every PREFIX in one panel: does the onset move
    with the resolution?"""
    styles = ["--", "-", "-.", ":"]
    colours = {mu: f"C{i}" for i, (_, mu) in enumerate(MUS)}
    fig, bx = plt.subplots(figsize=(6.5, 4))
    for k, (prefix, histories) in enumerate(histories_per_prefix):
        for mu, (t, a, _) in histories:
            bx.plot(shell_angle(t) / math.pi, shell_angle(t) - a,
                    styles[k % len(styles)], color=colours[mu],
                    label=f"{prefix}, mu = {mu:g}")
    finish_slip_axes(bx, 7)
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "twist_resolution.png"), dpi=80)
    plt.close(fig)


def main():
    arguments = sys.argv[1:]
    compare_only = "--compare" in arguments
    arguments = [a for a in arguments if a != "--compare"]
    root = arguments[0] if arguments else "output"
    prefixes = arguments[1:] or ["twist"]
    os.makedirs(IMAGES, exist_ok=True)
    histories_per_prefix = []
    for prefix in prefixes:
        runs = runs_of(root, prefix)
        if not runs:
            sys.exit(f"no runs {prefix}_mu* in {root}")
        histories = [(mu, twist_history(folder)) for mu, folder in runs]
        histories_per_prefix.append((prefix, histories))
        plot_prefix(prefix, histories, compare_only)
        if not compare_only:
            render([(f"mu = {mu:g}", folder) for mu, folder in runs],
                   os.path.join(IMAGES, f"twist_snapshots{suffix_of(prefix)}.png"))
    if len(prefixes) > 1:
        plot_resolutions(histories_per_prefix)


if __name__ == "__main__":
    main()
