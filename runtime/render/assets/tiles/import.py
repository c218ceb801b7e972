#!/usr/bin/env python3
"""Import the tile faces from FluffyStuff/riichi-mahjong-tiles (CC0).

Usage:  python3 import.py <riichi-mahjong-tiles>/Regular [output-dir]

The source is https://github.com/FluffyStuff/riichi-mahjong-tiles at commit
26e127ba2117f45cdce5ea0225748cc0cfad3169 ("Regular" set).  The output
directory defaults to the directory holding this script.  Standard library
only.

Each Inkscape SVG is reduced to one line:

    <svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 300 400">...</svg>

* <defs>, <metadata>, sodipodi/inkscape/RDF elements, comments, `id`
  attributes and every namespaced attribute are dropped.
* <use> clones (Pin1, Pin2, Sou1 build their rings with them) are expanded in
  place as <g transform="..."> copies, so no element needs an id and a face
  can be inlined into a larger SVG without id clashes.
* `style="..."` is turned into presentation attributes (fill, stroke,
  stroke-width, ...).  A property is dropped when it equals the value the
  element would inherit anyway (initial values at the root), when it cannot
  matter (stroke-* on an unstroked leaf, fill-* on an unfilled leaf, fill-rule
  on circles/ellipses), or when it is not drawing-related (font-*, ...).
* Coordinates are rounded so the error in viewBox units is about 0.05
  (one decimal place at the tile's scale; inside a group scaled down by ten
  that is whole numbers).  Relative path commands are rounded against the
  already-rounded current point, so errors do not accumulate along a path.
  The linear part of matrix() transforms keeps 6 decimals (rounding a
  rotation/scale coefficient to 0.1 would visibly distort the drawing).
* Groups left with no attributes are unwrapped, empty groups removed.
* A leaf with an opaque fill whose box covers >= 90 % of the viewBox (a tile
  body / background) is removed and reported.  The Regular faces have none;
  the body is Front.svg, which is not imported.
"""

import math
import os
import re
import sys
import xml.etree.ElementTree as ET

SVG = "http://www.w3.org/2000/svg"
XLINK = "http://www.w3.org/1999/xlink"

NAMES = {}
for _suit, _letter in (("Man", "m"), ("Pin", "p"), ("Sou", "s")):
    for _n in range(1, 10):
        NAMES[f"{_suit}{_n}"] = f"{_n}{_letter}"
    NAMES[f"{_suit}5-Dora"] = "0" + _letter
NAMES.update(
    {"Ton": "E", "Nan": "S", "Shaa": "W", "Pei": "N", "Haku": "P", "Hatsu": "F", "Chun": "C"}
)

# Inherited presentation properties we keep, with their initial values.
INHERITED = {
    "fill": "#000",
    "fill-opacity": "1",
    "fill-rule": "nonzero",
    "stroke": "none",
    "stroke-width": "1",
    "stroke-opacity": "1",
    "stroke-linecap": "butt",
    "stroke-linejoin": "miter",
    "stroke-miterlimit": "4",
    "stroke-dasharray": "none",
    "stroke-dashoffset": "0",
}
NON_INHERITED = {"opacity": "1"}
# Properties that would need <defs> or that we cannot carry over: refuse.
UNSUPPORTED = {"filter", "mask", "clip-path", "marker", "marker-start", "marker-mid", "marker-end"}
STROKE_PROPS = [p for p in INHERITED if p.startswith("stroke")]
FILL_PROPS = ["fill-opacity", "fill-rule"]
SHAPES = {"path", "circle", "ellipse", "rect", "line", "polyline", "polygon"}
GEOMETRY = [
    "d",
    "cx",
    "cy",
    "r",
    "rx",
    "ry",
    "x",
    "y",
    "width",
    "height",
    "x1",
    "y1",
    "x2",
    "y2",
    "points",
]
ATTR_ORDER = [
    "fill",
    "fill-opacity",
    "fill-rule",
    "stroke",
    "stroke-width",
    "stroke-opacity",
    "stroke-linecap",
    "stroke-linejoin",
    "stroke-miterlimit",
    "stroke-dasharray",
    "stroke-dashoffset",
    "opacity",
]

NUM = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def local(tag):
    return tag.rsplit("}", 1)[-1] if tag.startswith("{" + SVG + "}") else None


# ---------------------------------------------------------------- numbers


def fmt_int(n, d):
    """Format the integer n (in units of 10**-d) minimally."""
    if n == 0:
        return "0"
    neg = n < 0
    s = str(abs(n))
    if d > 0:
        s = s.rjust(d + 1, "0")
        s = (s[:-d] + "." + s[-d:]).rstrip("0").rstrip(".")
        if s.startswith("0."):
            s = s[1:]
    return ("-" if neg else "") + s


def q(x, d):
    """Round x to d decimals, returning an integer in units of 10**-d."""
    return int(math.floor(x * 10**d + 0.5))


def fmt(x, d):
    return fmt_int(q(x, d), d)


def join_nums(parts):
    """Join numbers with the fewest separators ("1-2.5.5" = 1, -2.5, .5)."""
    out = []
    last = ""
    for p in parts:
        if out and needs_sep(last, p):
            out.append(" ")
        out.append(p)
        last = p
    return "".join(out)


def needs_sep(last, p):
    return not (p.startswith("-") or (p.startswith(".") and "." in last))


def decimals_for(scale):
    """Decimals so that 0.5 * 10**-d * scale <= 0.05 viewBox units."""
    if scale <= 0:
        return 1
    # tolerate ~12 % overshoot (0.056 units) so scale 1.0000001 keeps 1 decimal
    return max(0, math.ceil(1 + math.log10(scale) - 0.05))


# ------------------------------------------------------------- transforms


def mat_mul(a, b):
    return (
        a[0] * b[0] + a[2] * b[1],
        a[1] * b[0] + a[3] * b[1],
        a[0] * b[2] + a[2] * b[3],
        a[1] * b[2] + a[3] * b[3],
        a[0] * b[4] + a[2] * b[5] + a[4],
        a[1] * b[4] + a[3] * b[5] + a[5],
    )


IDENT = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)


def parse_transform(s):
    """List of (name, [floats]) and the combined matrix."""
    items = []
    m = IDENT
    for name, args in re.findall(r"(\w+)\s*\(([^)]*)\)", s or ""):
        v = [float(x) for x in NUM.findall(args)]
        if name == "matrix":
            t = tuple(v)
        elif name == "translate":
            t = (1, 0, 0, 1, v[0], v[1] if len(v) > 1 else 0)
        elif name == "scale":
            t = (v[0], 0, 0, v[1] if len(v) > 1 else v[0], 0, 0)
        elif name == "rotate":
            a = math.radians(v[0])
            c, s_ = math.cos(a), math.sin(a)
            t = (c, s_, -s_, c, 0, 0)
            if len(v) == 3:
                t = mat_mul(mat_mul((1, 0, 0, 1, v[1], v[2]), t), (1, 0, 0, 1, -v[1], -v[2]))
        elif name == "skewX":
            t = (1, 0, math.tan(math.radians(v[0])), 1, 0, 0)
        elif name == "skewY":
            t = (1, math.tan(math.radians(v[0])), 0, 1, 0, 0)
        else:
            raise ValueError("unknown transform " + name)
        items.append((name, v))
        m = mat_mul(m, t)
    return items, m


def max_scale(m):
    """Largest singular value of the linear part."""
    a, b, c, d = m[:4]
    s1 = a * a + b * b + c * c + d * d
    det = a * d - b * c
    return math.sqrt((s1 + math.sqrt(max(0.0, s1 * s1 - 4 * det * det))) / 2)


def fmt_transform(items, parent_dec):
    out = []
    for name, v in items:
        if name == "matrix":
            lin = [fmt(x, 6) for x in v[:4]]
            tr = [fmt(x, parent_dec) for x in v[4:]]
            if lin == ["1", "0", "0", "1"]:
                if tr != ["0", "0"]:
                    out.append("translate({})".format(" ".join(tr)))
            else:
                out.append("matrix({})".format(" ".join(lin + tr)))
        elif name == "translate":
            tr = [fmt(x, parent_dec) for x in v]
            if len(tr) == 2 and tr[1] == "0":
                tr = tr[:1]
            if tr != ["0"]:
                out.append("translate({})".format(" ".join(tr)))
        elif name == "rotate":
            out.append(
                "rotate({})".format(" ".join([fmt(v[0], 4)] + [fmt(x, parent_dec) for x in v[1:]]))
            )
        else:
            out.append("{}({})".format(name, " ".join(fmt(x, 6) for x in v)))
    return " ".join(out)


# ------------------------------------------------------------------ paths

ARGC = {"m": 2, "l": 2, "h": 1, "v": 1, "c": 6, "s": 4, "q": 4, "t": 2, "a": 7, "z": 0}


def parse_path(d):
    toks = re.findall(r"[MmLlHhVvCcSsQqTtAaZz]|" + NUM.pattern, d)
    segs = []
    i = 0
    cmd = None
    while i < len(toks):
        t = toks[i]
        if t.isalpha():
            cmd = t
            i += 1
            if cmd in "zZ":
                segs.append((cmd, []))
                continue
        elif cmd is None:
            raise ValueError("path data must start with a command")
        n = ARGC[cmd.lower()]
        if cmd.lower() == "a":
            # arc flags may be written without separators ("a5 5 0 011 1")
            args = []
            while len(args) < 7:
                tok = toks[i]
                if (
                    len(args) in (3, 4)
                    and len(tok) > 1
                    and tok[0] in "01"
                    and not tok.startswith(("0.", "1."))
                ):
                    args.append(float(tok[0]))
                    toks[i] = tok[1:]
                    continue
                args.append(float(tok))
                i += 1
        else:
            args = [float(x) for x in toks[i : i + n]]
            i += n
        if len(args) != n:
            raise ValueError("truncated path data")
        segs.append((cmd, args))
        if cmd == "m":
            cmd = "l"
        elif cmd == "M":
            cmd = "L"
    return segs


def round_path(d, dec, points_out):
    """Round path data; append absolute (unrounded) points to points_out."""
    segs = parse_path(d)
    cx = cy = 0.0  # true current point
    rx = ry = 0  # rounded current point (ints, units 10**-dec)
    sx = sy = 0.0  # true subpath start
    srx = sry = 0
    out = []
    prev = None  # letter whose repetition may be implicit
    last = ""  # last number written

    for cmd, a in segs:
        up = cmd.upper()
        rel = cmd.islower()
        if up == "Z":
            out.append("z")
            prev = None
            cx, cy, rx, ry = sx, sy, srx, sry
            continue
        # absolute true coordinates of all points in this segment
        if up in "MLT":
            pts = [(a[0] + (cx if rel else 0), a[1] + (cy if rel else 0))]
        elif up == "H":
            pts = [(a[0] + (cx if rel else 0), cy)]
        elif up == "V":
            pts = [(cx, a[0] + (cy if rel else 0))]
        elif up in "CSQ":
            pts = [
                (a[k] + (cx if rel else 0), a[k + 1] + (cy if rel else 0))
                for k in range(0, len(a), 2)
            ]
        else:  # A
            pts = [(a[5] + (cx if rel else 0), a[6] + (cy if rel else 0))]
        qp = [(q(x, dec), q(y, dec)) for x, y in pts]

        def nums(relative, up=up, qp=qp, a=a, rx=rx, ry=ry):
            ox, oy = (rx, ry) if relative else (0, 0)
            if up == "H":
                return [fmt_int(qp[0][0] - ox, dec)]
            if up == "V":
                return [fmt_int(qp[0][1] - oy, dec)]
            res = []
            if up == "A":
                res = [fmt(a[0], dec), fmt(a[1], dec), fmt(a[2], 2), str(int(a[3])), str(int(a[4]))]
            for x, y in qp:
                res += [fmt_int(x - ox, dec), fmt_int(y - oy, dec)]
            return res

        best = None
        for relative in (True, False):
            letter = up.lower() if relative else up
            body = nums(relative)
            if letter == prev:  # command letter may be left implicit
                text = (" " if needs_sep(last, body[0]) else "") + join_nums(body)
            else:
                text = letter + join_nums(body)
            if best is None or len(text) < len(best[0]):
                best = (text, letter, body[-1])
        text, letter, last = best
        out.append(text)
        prev = {"m": "l", "M": "L"}.get(letter, letter)
        points_out.extend(pts)
        cx, cy = pts[-1]
        rx, ry = qp[-1]
        if up == "M":
            sx, sy, srx, sry = cx, cy, rx, ry
    s = "".join(out)
    return s


# ----------------------------------------------------------------- styles


def parse_style(el):
    props = {}
    for k in list(INHERITED) + list(NON_INHERITED) + list(UNSUPPORTED) + ["display", "visibility"]:
        if el.get(k) is not None:
            props[k] = el.get(k).strip()
    for part in (el.get("style") or "").split(";"):
        if ":" in part:
            k, v = part.split(":", 1)
            props[k.strip()] = v.strip()
    return props


def norm_color(v):
    v = v.lower()
    m = re.fullmatch(r"#([0-9a-f])\1([0-9a-f])\2([0-9a-f])\3", v)
    if m:
        return "#" + "".join(m.groups())
    return {"black": "#000", "white": "#fff"}.get(v, v)


def norm_value(k, v, dec):
    v = v.strip()
    if k in ("fill", "stroke"):
        return norm_color(v)
    if k in ("stroke-width", "stroke-dashoffset"):
        return fmt(float(re.sub(r"px$", "", v)), dec + 1)
    if k == "stroke-dasharray":
        if v == "none":
            return v
        return ",".join(fmt(float(x), dec + 1) for x in NUM.findall(v))
    if k in ("opacity", "fill-opacity", "stroke-opacity", "stroke-miterlimit"):
        return fmt(float(v), 3)
    return v


# ---------------------------------------------------------------- convert


class Face:
    def __init__(self, root):
        self.ids = {e.get("id"): e for e in root.iter() if e.get("id")}
        self.warnings = []
        self.removed = []
        self.boxes = []
        vb = root.get("viewBox")
        if vb is None:
            vb = "0 0 {} {}".format(root.get("width"), root.get("height"))
        self.viewbox = [float(x) for x in NUM.findall(vb)]

    def convert(self, el, ctm, dec_parent, inherited, depth=0):
        """Return a list of output strings for el (possibly empty)."""
        if depth > 50:
            raise ValueError("<use> recursion too deep")
        tag = local(el.tag)
        if tag is None or tag in ("defs", "metadata", "title", "desc"):
            return []
        if tag == "use":
            return self.expand_use(el, ctm, dec_parent, inherited, depth)
        if tag not in SHAPES and tag not in ("g", "svg"):
            self.warnings.append(f"dropped <{tag}>")
            return []

        props = parse_style(el)
        for k in UNSUPPORTED:
            if k in props and props[k] != "none":
                raise ValueError(f"{k}={props[k]} needs <defs>; not supported")
        if props.get("display") == "none" or props.get("visibility") == "hidden":
            return []

        items, m = parse_transform(el.get("transform"))
        ctm2 = mat_mul(ctm, m)
        dec = decimals_for(max_scale(ctm2))

        # computed values
        comp = dict(inherited)
        for k in INHERITED:
            if k in props:
                comp[k] = norm_value(k, props[k], dec)
        opacity = norm_value("opacity", props.get("opacity", "1"), dec)

        # which properties to write
        attrs = {}
        leaf = tag in SHAPES
        for k in INHERITED:
            if comp[k] != inherited[k]:
                attrs[k] = comp[k]
        if opacity != "1":
            attrs["opacity"] = opacity
        if leaf:
            stroked = (
                comp["stroke"] != "none"
                and comp["stroke-opacity"] != "0"
                and comp["stroke-width"] != "0"
            )
            filled = comp["fill"] != "none" and comp["fill-opacity"] != "0"
            if not stroked:
                for k in STROKE_PROPS:
                    attrs.pop(k, None)
                if comp["stroke"] != inherited["stroke"] and inherited["stroke"] != "none":
                    attrs["stroke"] = "none"
            else:
                if comp["stroke-linejoin"] != "miter":
                    attrs.pop("stroke-miterlimit", None)
                if comp["stroke-dasharray"] == "none":
                    attrs.pop("stroke-dashoffset", None)
            if not filled:
                for k in FILL_PROPS:
                    attrs.pop(k, None)
            if tag in ("circle", "ellipse", "rect", "line"):
                attrs.pop("fill-rule", None)
            if not filled and not stroked:
                return []

        geom = []
        points = []
        if tag == "path":
            geom.append(("d", round_path(el.get("d", ""), dec, points)))
        else:
            for k in GEOMETRY:
                v = el.get(k)
                if v is None:
                    continue
                if k == "points":
                    nums = [float(x) for x in NUM.findall(v)]
                    points += list(zip(nums[::2], nums[1::2]))
                    geom.append((k, join_nums([fmt(x, dec) for x in nums])))
                elif v.endswith("%"):
                    geom.append((k, v))
                else:
                    geom.append((k, fmt(float(v), dec)))
            g = {
                k: float(el.get(k))
                for k in GEOMETRY
                if el.get(k) is not None and k != "points" and not el.get(k).endswith("%")
            }
            if tag == "circle":
                r = g.get("r", 0)
                points += [
                    (g.get("cx", 0) + sx * r, g.get("cy", 0) + sy * r)
                    for sx in (-1, 1)
                    for sy in (-1, 1)
                ]
            elif tag == "ellipse":
                points += [
                    (g.get("cx", 0) + sx * g.get("rx", 0), g.get("cy", 0) + sy * g.get("ry", 0))
                    for sx in (-1, 1)
                    for sy in (-1, 1)
                ]
            elif tag == "rect":
                x, y = g.get("x", 0), g.get("y", 0)
                points += [
                    (x + sx * g.get("width", 0), y + sy * g.get("height", 0))
                    for sx in (0, 1)
                    for sy in (0, 1)
                ]
            elif tag == "line":
                points += [(g.get("x1", 0), g.get("y1", 0)), (g.get("x2", 0), g.get("y2", 0))]

        tf = fmt_transform(items, dec_parent)

        if leaf and points:
            tp = [
                (ctm2[0] * x + ctm2[2] * y + ctm2[4], ctm2[1] * x + ctm2[3] * y + ctm2[5])
                for x, y in points
            ]
            box = (
                min(p[0] for p in tp),
                min(p[1] for p in tp),
                max(p[0] for p in tp),
                max(p[1] for p in tp),
            )
            vx, vy, vw, vh = self.viewbox
            cover = (
                max(0, min(box[2], vx + vw) - max(box[0], vx))
                * max(0, min(box[3], vy + vh) - max(box[1], vy))
            ) / (vw * vh)
            opaque = filled and comp["fill-opacity"] == "1" and opacity == "1"
            if opaque and cover >= 0.9:
                self.removed.append(
                    "<{}> fill={} covering {:.0f}%".format(tag, comp["fill"], cover * 100)
                )
                return []
            self.boxes.append(box)

        children = []
        if not leaf:
            for c in el:
                children += self.convert(c, ctm2, dec, comp, depth)
            if not children:
                return []

        out_attrs = geom[:]
        if tf:
            out_attrs.append(("transform", tf))
        out_attrs += [(k, attrs[k]) for k in ATTR_ORDER if k in attrs]

        if tag == "svg":
            return children
        if tag == "g" and not out_attrs:
            return children  # attribute-less group: unwrap
        open_ = "<{}{}".format(tag, "".join(f' {k}="{xml_escape(v)}"' for k, v in out_attrs))
        if leaf:
            return [open_ + "/>"]
        return [open_ + ">"] + children + [f"</{tag}>"]

    def expand_use(self, el, ctm, dec_parent, inherited, depth):
        href = el.get(f"{{{XLINK}}}href") or el.get("href")
        if not href or not href.startswith("#") or href[1:] not in self.ids:
            raise ValueError(f"unresolvable <use> {href!r}")
        target = self.ids[href[1:]]
        g = ET.Element(f"{{{SVG}}}g")
        tf = el.get("transform") or ""
        x, y = float(el.get("x", 0) or 0), float(el.get("y", 0) or 0)
        if x or y:
            tf += f" translate({x!r},{y!r})"
        if tf.strip():
            g.set("transform", tf.strip())
        for k, v in el.attrib.items():
            if k == "style" or k in INHERITED or k in NON_INHERITED:
                g.set(k, v)
        g.append(target)  # shared, not copied: convert() does not mutate
        return self.convert(g, ctm, dec_parent, inherited, depth + 1)


def xml_escape(v):
    return v.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")


def convert_file(path):
    root = ET.parse(path).getroot()
    face = Face(root)
    vx, vy, vw, vh = face.viewbox
    vb = join_nums([fmt(v, 3) for v in face.viewbox])
    inherited = dict(INHERITED)
    body = []
    for c in root:
        body += face.convert(c, IDENT, 1, inherited)
    svg = '<svg xmlns="{}" viewBox="{}">{}</svg>'.format(SVG, vb, "".join(body))
    ET.fromstring(svg)  # must still be well-formed
    return svg, face


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    src = argv[1]
    dst = argv[2] if len(argv) == 3 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(dst, exist_ok=True)
    total = 0
    for name, short in NAMES.items():
        svg, face = convert_file(os.path.join(src, name + ".svg"))
        out = os.path.join(dst, short + ".svg")
        with open(out, "w", encoding="utf-8", newline="\n") as f:
            f.write(svg + "\n")
        size = len(svg.encode()) + 1
        total += size
        note = []
        if face.viewbox != [0, 0, 300, 400]:
            note.append(f"viewBox {face.viewbox}")
        if face.removed:
            note.append("REMOVED background: " + "; ".join(face.removed))
        note += face.warnings
        print(f"{name + '.svg':<14} -> {short + '.svg':<6} {size:>6} bytes {'  '.join(note)}")
    print(f"total {total} bytes in {len(NAMES)} files")


if __name__ == "__main__":
    main(sys.argv)
