"""matplotlib figures shared by the drivers (Agg backend, PNG)."""
import os

import numpy as np


def pyplot():
    """matplotlib.pyplot on the Agg backend with the drivers' font size and resolution."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.rcParams.update({"font.size": 9, "savefig.dpi": 110})
    return plt


def save(fig, path):
    """Saves to a temporary name and renames (a failed run never leaves a figure that looks complete)."""
    plt = pyplot()
    root, ext = os.path.splitext(path)
    tmp = root + ".tmp" + ext
    fig.savefig(tmp, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
    return path


def plot_split_at(ax, t, y, t_split, color, label, split_label="past the first inverted element", lw=1.2):
    """Draws y(t) solid up to t_split and dashed after it (labelled), e.g. a FEM curve past the time its
    mesh first inverted. t_split None: one solid curve."""
    t, y = np.asarray(t), np.asarray(y)
    if t_split is None or t_split >= t[-1]:
        ax.plot(t, y, "-", color=color, label=label, lw=lw)
        return
    k = int(np.searchsorted(t, t_split, side="right"))
    ax.plot(t[:k + 1], y[:k + 1], "-", color=color, label=label, lw=lw)
    ax.plot(t[k:], y[k:], "--", color=color, label="%s, %s" % (label, split_label), lw=lw)


def plot_fem_mesh(ax, xy, elems, u, cmap="viridis", vmax=None):
    """The FEM mesh deformed by nodal displacements u (n x 2), elements coloured by the mean |u| of their
    nodes, over the undeformed mesh edges in grey. Returns the collection (for a colour bar)."""
    from matplotlib.collections import PolyCollection
    ax.add_collection(PolyCollection(xy[elems], facecolors="none", edgecolors="0.75", linewidths=0.3))
    cur = xy + u
    mag = np.linalg.norm(u, axis=1)[elems].mean(axis=1)
    pc = PolyCollection(cur[elems], array=mag, cmap=cmap, edgecolors="k", linewidths=0.15)
    pc.set_clim(0.0, vmax if vmax else max(float(mag.max()), 1e-12))
    ax.add_collection(pc)
    lo, hi = np.minimum(xy.min(axis=0), cur.min(axis=0)), np.maximum(xy.max(axis=0), cur.max(axis=0))
    pad = 0.03 * (hi - lo).max()
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    return pc


def plot_particles(ax, x, y, c, spacing, vmin=0.0, vmax=None, cmap="viridis"):
    """Particles as squares of their spacing (so the cloud looks like the material), coloured by c."""
    fig = ax.figure
    ax.set_aspect("equal")
    ax.set_xlim(x.min() - spacing, x.max() + spacing)
    ax.set_ylim(y.min() - spacing, y.max() + spacing)
    fig.canvas.draw()
    # marker size in points^2 from the particle spacing in data units
    bbox = ax.get_window_extent()
    pts_per_unit = bbox.width / (ax.get_xlim()[1] - ax.get_xlim()[0]) * 72.0 / fig.dpi
    s = max((1.15 * spacing * pts_per_unit) ** 2, 0.3)
    return ax.scatter(x, y, c=c, s=s, marker="s", linewidths=0, cmap=cmap, vmin=vmin,
                      vmax=vmax if vmax else max(float(np.max(c)), 1e-12))
