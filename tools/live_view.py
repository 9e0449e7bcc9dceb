#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Live view of a drive: for each corner, the operating point moving over
its stability map, coloured by the state the monitor reports, with the Hopf
margin and the warning level over the last seconds.

usage: live_view.py (--iface IF | --log FILE [--rate X]) [--calib FILE]
                    [--snapshot FILE.png --after S] [--window S]
                    [--v-max MPS] [--force-max N] [--interface NAME]

Input: the monitor's frames SquealStatus (state, warning, Hopf margin),
SquealDetail (v0) and SquealDetail2 (pad force) of the calibration's corners
(without [corner] sections FL, FR, RL, RR on its identifiers + 0x10 k; with
them each corner on its own status_id/detail_id/detail2_id, over the map of
its own brake), decoded with canmatrix from firmware/protocol/squeal.dbc;
other frames are ignored. A log without a single monitor frame (e.g. the
plant's input log, before `squeal-sim replay`) is refused: nothing is drawn.
The map's speed axis is stretched where the borders are (0 to a little past
the speed at which the stability limit reaches --force-max), compressed
beyond; the regions and lines are in the legend.
With --snapshot FILE.png the picture is written at 150 dpi with FILE.svg
beside it. The map is the closed-form one of the physics model (scipy,
tools/plots/plotlib.py).
Exit status: 0 done, 1 input error (unreadable log, no monitor frames, interface), 2 bad usage.
"""
import argparse
import collections
import math
import os
import sys
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import matplotlib  # noqa: E402
_GUI_BACKEND = matplotlib.get_backend()
import drive_common as DC  # noqa: E402  (plotlib selects Agg)

P = DC.P
KINDS = ("SquealStatus", "SquealDetail", "SquealDetail2")
MAP_ALPHA = 0.55   # the regions behind the trail


def load_dbc(path=DC.DBC):
    import logging
    logging.getLogger("canmatrix").setLevel(logging.ERROR)  # "xls is not supported" etc.
    import canmatrix.formats
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        dbs = canmatrix.formats.loadp(path)
    return list(dbs.values())[0]


class Corner:
    """What one corner reported: the latest values and a time window."""

    def __init__(self, name, window_s):
        self.name = name
        self.window_s = window_s
        self.v0 = self.force = self.margin = None
        self.state, self.warning = "fault", 0
        self.trail = collections.deque()   # (t, v0, force, state)
        self.hist = collections.deque()    # (t, margin or nan, warning)

    def trim(self, now):
        for dq in (self.trail, self.hist):
            while dq and dq[0][0] < now - self.window_s:
                dq.popleft()


class LiveView:
    def __init__(self, calib, window_s=10.0, v_max=14.0, n_max=20000.0):
        self.setup = {c.name: c for c in DC.corners(calib)}
        self.ids = {}
        for c in self.setup.values():
            for kind, cid in zip(KINDS, c.ids):
                self.ids[cid] = (c.name, kind)
        self.db = load_dbc()
        self.msgs = {kind: self.db.frame_by_name(kind) for kind in KINDS}
        self.window_s, self.v_max, self.n_max = window_s, v_max, n_max
        self.corners = {}
        self.now = None
        self.frames = 0
        self.fig = None
        self.drawn_corners = ()

    # ---- input ----------------------------------------------------------
    def _decode(self, kind, data):
        msg = self.msgs[kind]
        if len(data) != msg.size:
            return None
        out = {}
        for name, d in msg.decode(bytes(data)).items():
            na = msg.signal_by_name(name).values.get(d.raw_value) == "not_available"
            out[name] = None if na else float(d.phys_value)
        return out

    def on_frame(self, t, can_id, data):
        """One frame at bus time t [s]; True if it was one of ours."""
        key = self.ids.get(can_id)
        if key is None:
            return False
        name, kind = key
        sig = self._decode(kind, data)
        if sig is None:
            return False
        c = self.corners.setdefault(name, Corner(name, self.window_s))
        self.now = t
        self.frames += 1
        if kind == "SquealStatus":
            raw = int(sig["SquealState"])
            c.state = DC.STATES[raw] if raw < 4 else "fault"
            c.warning = int(sig["WarningLevel"])
            c.margin = sig["HopfMargin_mps"]
            c.hist.append((t, math.nan if c.margin is None else c.margin, c.warning))
        elif kind == "SquealDetail":
            c.v0 = sig["V0_mps"]
        else:
            c.force = sig["Force_N"]
        if kind != "SquealStatus" and c.v0 is not None and c.force is not None:
            c.trail.append((t, c.v0, c.force, c.state))
        c.trim(t)
        return True

    # ---- drawing ----------------------------------------------------------
    def _build(self):
        plt = P.plt
        names = [n for n in DC.CORNERS if n in self.corners] or [min(self.setup, key=DC.CORNERS.index)]
        if self.fig is not None:
            plt.close(self.fig)
        height = 5.0 * len(names) + 1.0   # + the legend's inch
        self.fig = plt.figure(figsize=(11.0, height), dpi=80)
        gs = self.fig.add_gridspec(2 * len(names), 2, width_ratios=(1.25, 1.0), hspace=0.55,
                                   wspace=0.25, bottom=1.35 / height, top=1.0 - 0.55 / height)
        self.axes = {}
        for i, name in enumerate(names):
            ax = self.fig.add_subplot(gs[2 * i:2 * i + 2, 0])
            brake = self.setup[name]
            P.draw_map(ax, brake.brake, self.v_max, self.n_max, brake.criterion, alpha=MAP_ALPHA)
            if i == 0:  # one legend under all corners: it hides no point
                handles, _ = ax.get_legend_handles_labels()
                self.fig.legend(handles=handles + P.region_handles(alpha=MAP_ALPHA) +
                                P.reported_handles(("stable", "bistable", "unstable"),
                                                   "point, trail: reported ", short=True),
                                loc="lower left", bbox_to_anchor=(0.04, 0.0), ncol=3,
                                fontsize=7.5, frameon=False)
            trail = ax.scatter([], [], s=9, zorder=4)
            point = ax.scatter([], [], s=190, edgecolors="k", linewidths=1.6, zorder=5)
            title = ax.set_title(name, fontsize=10, loc="left")
            am = self.fig.add_subplot(gs[2 * i, 1])
            aw = self.fig.add_subplot(gs[2 * i + 1, 1], sharex=am)
            (mline,) = am.plot([], [], color="#2166ac", label="Hopf margin (reported)")
            am.axhline(0.0, color=P.LINE_HOPF["color"], lw=1.0, label="0: on the Hopf border")
            am.legend(fontsize=7, loc="upper left")
            am.set_ylabel("Hopf margin [m/s]", fontsize=8)
            (wline,) = aw.step([], [], where="post", color="#b2182b", label="warning level (reported)")
            aw.set_ylim(-0.3, 3.3)
            aw.set_yticks([0, 1, 2, 3])
            aw.set_yticklabels(P.WARNING_TICKS, fontsize=7)
            aw.set_ylabel("warning level", fontsize=8)
            aw.set_xlabel("time [s] (0 = now)", fontsize=8)
            for a in (am, aw):
                a.set_xlim(-self.window_s, 0.0)
                a.grid(alpha=0.3)
            self.axes[name] = dict(map=ax, trail=trail, point=point, title=title, margin=am,
                                   mline=mline, warn=aw, wline=wline)
        self.drawn_corners = tuple(names)

    def draw(self):
        from matplotlib.colors import to_rgba
        names = tuple(n for n in DC.CORNERS if n in self.corners)
        if self.fig is None or (names and names != self.drawn_corners):
            self._build()
        now = self.now if self.now is not None else 0.0
        for name, a in self.axes.items():
            c = self.corners.get(name)
            if c is None:
                a["title"].set_text("%s: no frames yet" % name)
                continue
            if c.trail:
                a["trail"].set_offsets([(v, n / 1000.0) for _, v, n, _ in c.trail])
                a["trail"].set_facecolors([to_rgba(P.PATH_COLORS[s], 0.55) for *_, s in c.trail])
            if c.v0 is not None and c.force is not None:
                a["point"].set_offsets([(min(c.v0, self.v_max), min(c.force, self.n_max) / 1000.0)])
                a["point"].set_facecolors([P.PATH_COLORS[c.state]])
            ts = [t - now for t, _, _ in c.hist]
            a["mline"].set_data(ts, [m for _, m, _ in c.hist])
            a["wline"].set_data(ts, [w for _, _, w in c.hist])
            ms = [m for _, m, _ in c.hist if not math.isnan(m)]
            if ms:
                lo, hi = min(ms + [0.0]), max(ms + [0.0])
                a["margin"].set_ylim(lo - 0.1 * (hi - lo) - 0.05, hi + 0.1 * (hi - lo) + 0.05)
            a["title"].set_text("%s  t = %.2f s: %s, warning %d %s\nv0 %s m/s, N %s N, "
                                "Hopf margin %s m/s" % (
                                    name, now, P.state_label(c.state), c.warning,
                                    P.WARNING_NAMES[min(max(c.warning, 0), 3)], _fmt(c.v0),
                                    _fmt(c.force, 0), _fmt(c.margin)))
        return self.fig


def _fmt(x, nd=2):
    return "-" if x is None else "%.*f" % (nd, x)


# ---- sources ---------------------------------------------------------------

def run_log(view, path, rate, after_s=None, on_tick=None):
    """Feed a candump -L log; stop after after_s seconds of log time."""
    import can
    t_first = None
    wall0 = time.monotonic()
    next_draw = 0.0
    for msg in can.LogReader(path):
        if msg.is_error_frame or msg.is_remote_frame or msg.is_extended_id:
            continue
        if t_first is None:
            t_first = msg.timestamp
        t = msg.timestamp - t_first
        if after_s is not None and t > after_s:
            break
        if rate > 0:
            wait = t / rate - (time.monotonic() - wall0)
            if wait > 0:
                time.sleep(wait)
        view.on_frame(t, msg.arbitration_id, msg.data)
        if on_tick is not None and time.monotonic() >= next_draw:
            on_tick()
            next_draw = time.monotonic() + 0.1
    return t_first is not None


def run_bus(view, bus, after_s=None, on_tick=None, stop=lambda: False):
    """Frames from a python-can bus; bus time = wall time since the start."""
    wall0 = time.monotonic()
    next_draw = 0.0
    while not stop():
        t = time.monotonic() - wall0
        if after_s is not None and t >= after_s:
            break
        msg = bus.recv(timeout=0.05)
        if msg is not None and not (msg.is_error_frame or msg.is_remote_frame or msg.is_extended_id):
            view.on_frame(time.monotonic() - wall0, msg.arbitration_id, msg.data)
        if on_tick is not None and time.monotonic() >= next_draw:
            on_tick()
            next_draw = time.monotonic() + 0.1


def main(argv=None):
    ap = argparse.ArgumentParser(
        prog="live_view.py",
        description=__doc__.split("\nusage:")[0] + "\n\n" + __doc__[__doc__.index("Input:"):__doc__.index("Exit status:")],
        epilog=__doc__.split("Exit status:")[1].join(("Exit status:", "")).strip(),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--iface", metavar="IF", help="read a CAN interface live (e.g. vcan0, can0)")
    src.add_argument("--log", metavar="FILE", help="play a candump -L log (e.g. squeal-sim replay's output)")
    ap.add_argument("--rate", type=float, metavar="X",
                    help="playback speed of --log, x its own (default 1, with --snapshot 0; 0 = no waiting)")
    ap.add_argument("--calib", metavar="FILE",
                    help="calibration text file: corners, their brakes and identifiers (default: paper's brake, FL..RR)")
    ap.add_argument("--snapshot", metavar="FILE.png",
                    help="headless: write FILE.png (150 dpi) and FILE.svg after --after seconds and exit")
    ap.add_argument("--after", type=float, metavar="S",
                    help="seconds into the drive for --snapshot (log time; wall time on --iface)")
    ap.add_argument("--window", type=float, default=10.0, metavar="S",
                    help="seconds of history in the trail and time plots (default 10)")
    ap.add_argument("--v-max", type=float, default=14.0, metavar="MPS",
                    help="map's disc surface speed range [m/s] (default 14)")
    ap.add_argument("--force-max", type=float, default=20000.0, metavar="N",
                    help="map's pad force range [N] (default 20000)")
    ap.add_argument("--interface", default="socketcan", metavar="NAME",
                    help="python-can interface type of --iface (default socketcan)")
    args = ap.parse_args(argv)
    if (args.snapshot is None) != (args.after is None):
        ap.error("--snapshot FILE.png and --after S go together")
    if (args.after is not None and args.after < 0) or args.window <= 0 or args.v_max <= 0 \
            or args.force_max <= 0 or (args.rate is not None and args.rate < 0):
        ap.error("--after, --rate must be >= 0; --window, --v-max, --force-max > 0")
    if args.rate is not None and args.iface:
        ap.error("--rate goes with --log")
    try:
        view = LiveView(DC.read_calib(args.calib), args.window, args.v_max, args.force_max)
    except DC.CalibError as e:
        print("live_view: %s" % e, file=sys.stderr)
        return 2
    headless = args.snapshot is not None
    plt = P.plt
    tick = None
    if not headless:
        plt.switch_backend(_GUI_BACKEND)
        plt.ion()

        def tick():
            view.draw()
            plt.pause(0.001)
    rate = args.rate if args.rate is not None else (0.0 if headless else 1.0)
    try:
        if args.log:
            if not os.path.isfile(args.log):
                print("live_view: %s: no such log file" % args.log, file=sys.stderr)
                return 1
            if not run_log(view, args.log, rate, args.after, tick):
                print("live_view: %s: no CAN frames" % args.log, file=sys.stderr)
                return 1
        else:
            import can
            with can.Bus(interface=args.interface, channel=args.iface) as bus:
                run_bus(view, bus, args.after, tick)
    except (ValueError, OSError, can_errors()) as e:
        print("live_view: %s: %s" % (args.log or args.iface, e), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0
    if view.frames == 0 and (headless or args.log):
        print("live_view: %s: no monitor frames (SquealStatus, SquealDetail, SquealDetail2 on "
              "%s): nothing to draw" % (args.log or args.iface, ", ".join(
                  "0x%X" % i for i in sorted(view.ids))), file=sys.stderr)
        return 1
    fig = view.draw()
    if headless:
        P.save_as(fig, args.snapshot, tight=False)
        print("live_view: %d frames, %s at t = %.2f s -> %s" % (
            view.frames, ", ".join("%s %s" % (c.name, c.state) for c in view.corners.values()) or "no corner",
            view.now or 0.0, args.snapshot))
    else:
        plt.ioff()
        plt.show()
    return 0


def can_errors():
    import can
    return can.CanError


if __name__ == "__main__":
    sys.exit(main())
