#!/usr/bin/python3
"""Checks the HTML report of `ugo report` against its solution file (tests/io/report.rs).

    report_check.py PAGE.html SOLUTION.h5

The page is parsed strictly with the standard library's html.parser: every tag closed in
order, every table row as long as its header, every image a data: URI whose base64 decodes
to a whole PNG, no reference outside the file. The numbers of the tables are read back and
compared with the HDF5 file (h5py) as the page rounds them; the surfaces' mean illuminance
is derived here again from /field/illuminance and /mesh, and each glare grid's largest UGR
per position from /glare_grids/<name>/ugr; each grid's UGR (its attribute `UGR`, shown in
the grids' and light scenes' tables) is derived again as the largest of the observers and
the glare grids that name it (/observers/grid, /glare_grids/<name> attribute `grid`), for
the case and each light scene; each light scene's observers' UGR is checked with its
colour against /observers/ugr_limit, and the probes' table (illuminance ± bar, direct
part, luminance, and the illuminance ± bar in each light scene) against /probes and
/light_scenes/<name>/probes. Prints "report_check: ok".
"""

import base64
import struct
import sys
from html.parser import HTMLParser

import h5py
import numpy as np

VOID = {"meta", "img", "br", "hr", "link", "input", "col", "area", "base", "source", "wbr"}


def fail(message):
    sys.exit(f"report_check: {message}")


class Page(HTMLParser):
    """The page's tags checked as they come, its tables and images kept."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.tables, self.images, self.doctype = [], {}, [], False
        self.table, self.row, self.cell, self.cell_class = None, None, None, None

    def handle_decl(self, decl):
        self.doctype = decl.lower() == "doctype html"

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        for name, value in attrs.items():
            v = (value or "").strip().lower()
            if name in ("href", "src", "action", "poster", "srcset") and not v.startswith("data:"):
                fail(f"<{tag} {name}=\"{value}\"> refers outside the file")
        if tag in ("script", "link", "iframe", "object", "embed"):
            fail(f"<{tag}> in a self-contained report")
        if tag == "img":
            self.images.append(attrs.get("src", ""))
        if tag == "table":
            self.table = {"head": [], "rows": [], "classes": []}
            self.tables[attrs.get("id", f"table{len(self.tables)}")] = self.table
        elif tag == "tr":
            self.row = []
        elif tag in ("td", "th"):
            self.cell, self.cell_class = "", None
        elif tag == "span" and self.cell is not None:
            self.cell_class = attrs.get("class")
        if tag not in VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag, attrs):
        if tag not in VOID:
            fail(f"<{tag}/> is not a void element")
        self.handle_starttag(tag, attrs)
        self.stack.pop() if tag not in VOID else None

    def handle_endtag(self, tag):
        if tag in VOID:
            fail(f"</{tag}> closes a void element")
        if not self.stack or self.stack[-1] != tag:
            fail(f"</{tag}> closes <{self.stack[-1] if self.stack else 'nothing'}> (line {self.getpos()[0]})")
        self.stack.pop()
        if tag in ("td", "th"):
            self.row.append((tag, self.cell.strip(), self.cell_class))
            self.cell = None
        elif tag == "tr":
            kinds = {k for k, _, _ in self.row}
            cells = [c for _, c, _ in self.row]
            if kinds == {"th"} and not self.table["head"]:
                self.table["head"] = cells
            else:
                self.table["rows"].append(cells)
                self.table["classes"].append([c for _, _, c in self.row])

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data
        if "url(" in data:
            fail("a url( in the page refers outside it")


def check_png(src):
    prefix = "data:image/png;base64,"
    if not src.startswith(prefix):
        fail(f"an image is not a PNG data: URI: {src[:40]}")
    data = base64.b64decode(src[len(prefix):], validate=True)
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR" or data[-8:-4] != b"IEND":
        fail("an image does not decode to a whole PNG")
    width, height = struct.unpack(">II", data[16:24])
    if width < 100 or height < 100:
        fail(f"an image of {width} x {height} pixels")


def shown(value, decimals):
    return f"{value:.{decimals}f}" if np.isfinite(value) else "—"


def same(cell, value, decimals, what):
    if cell != shown(value, decimals):
        fail(f"{what}: the page shows {cell}, the file holds {value}")


def same_with_bar(cell, attrs, key, decimals, what):
    """A statistic shown with its error bar ("value ± bar") where the file holds a finite one."""
    bar = attrs.get(f"{key}_error")
    value = shown(attrs[key], decimals)
    expected = f"{value} ± {bar:.{decimals}f}" if bar is not None and np.isfinite(bar) and value != "—" else value
    if cell != expected:
        fail(f"{what}: the page shows {cell}, the file holds {attrs[key]} ± {bar}")


def check_grids(table, h5, prefix="grids"):
    for row in table["rows"]:
        name = row[0]
        g = h5[f"{prefix}/{name}"]
        counted = np.asarray(g["counted"])
        if row[1] != f"{int(counted.sum())} of {counted.size}":
            fail(f"grid {name}: points counted {row[1]}")
        check_stats(row[2:], g.attrs, f"grid {name}")


def check_stats(cells, attrs, what):
    """E_avg, Ēm target, E_min, E_max, U0, U0 target, UGR, UGR_L, meets targets."""
    em = attrs.get("Em_target")
    u0t = attrs.get("U0_target")
    ugr = attrs.get("UGR")
    ugr_l = attrs.get("UGR_target")
    same_with_bar(cells[0], attrs, "E_avg", 1, f"{what} E_avg")
    same(cells[1], em if em is not None else np.nan, 0, f"{what} Ēm target")
    same_with_bar(cells[2], attrs, "E_min", 1, f"{what} E_min")
    same(cells[3], attrs["E_max"], 1, f"{what} E_max")
    same_with_bar(cells[4], attrs, "U0", 2, f"{what} U0")
    same(cells[5], u0t if u0t is not None else np.nan, 2, f"{what} U0 target")
    glare = "-" if ugr is None else (f"{ugr:.1f}" if np.isfinite(ugr) else "no source")
    if cells[6] != glare:
        fail(f"{what}: UGR shows {cells[6]}, the file holds {ugr}")
    same(cells[7], ugr_l if ugr_l is not None else np.nan, 0, f"{what} UGR_L")
    checks = ([attrs["E_avg"] >= em] if em is not None else []) + ([attrs["U0"] >= u0t] if u0t is not None else [])
    checks += [ugr is not None and ugr <= ugr_l] if ugr_l is not None else []
    expected = "—" if not checks else ("yes" if all(checks) else "no")
    if cells[8] != expected:
        fail(f"{what}: meets targets shows {cells[8]}, expected {expected}")


def check_luminaires(table, h5):
    lum = h5["luminaires"]
    kinds = [k.decode() if isinstance(k, bytes) else k for k in lum["kind"][()]]
    electric = [i for i, k in enumerate(kinds) if k != "window"]
    flux = np.asarray(lum["flux"])[electric]
    count = sum(int(r[3]) for r in table["rows"])
    if count != len(electric):
        fail(f"the luminaire table counts {count} luminaires, the file has {len(electric)}")
    total = sum(float(r[7]) for r in table["rows"])
    if abs(total - flux.sum()) > 0.05 * len(table["rows"]) + 1e-9:
        fail(f"the luminaires' maintained flux sums to {total} lm, the file's to {flux.sum()} lm")
    mf = lum.attrs["maintenance_factor"]
    for r in table["rows"]:
        same(r[5], mf, 2, "maintenance factor")


def check_surfaces(table, h5):
    """Each surface's mean illuminance derived again: front patches (not a back twin), by side."""
    e = np.asarray(h5["field/illuminance"])
    area = np.asarray(h5["mesh/areas"])
    surface = np.asarray(h5["mesh/surface_id"])
    twin = np.asarray(h5["mesh/twin"]).astype(np.int64)
    ny = np.asarray(h5["mesh/normals"])[:, 1]
    names = [n.decode() if isinstance(n, bytes) else n for n in h5["mesh/surface_names"][()]]
    front = (twin == 2**32 - 1) | (twin > np.arange(len(twin)))
    side = np.where(ny > 0.7, 0, np.where(ny < -0.7, 1, np.where(np.abs(ny) < 0.3, 2, 3)))
    sides = ["up (floor)", "down (ceiling)", "vertical (wall)", "sloped"]
    expected = []
    for s, name in enumerate(names):
        for k, label in enumerate(sides):
            m = front & (surface == s) & (side == k)
            if m.any():
                mean = (area[m] * e[m]).sum() / area[m].sum()
                expected.append([name, label, shown(area[m].sum(), 2), shown(mean, 1), shown(e[m].min(), 1), shown(e[m].max(), 1)])
    got = [[r[0], r[2], r[3], r[4], r[5], r[6]] for r in table["rows"]]
    if got != expected:
        fail(f"the surfaces' table differs from the field: {got[:3]} against {expected[:3]}")


def check_daylight(table, h5):
    for row in table["rows"]:
        attrs = h5[f"daylight/grids/{row[0]}"].attrs
        for cell, key in zip(row[1:], ["DF_avg", "DF_min", "DF_max", "uniformity"]):
            same(cell, attrs[key], 2, f"daylight of grid {row[0]}: {key}")


def check_observers(table, h5):
    ugr = np.asarray(h5["observers/ugr"])
    for row, value in zip(table["rows"], ugr):
        if row[1] != (f"{value:.1f}" if np.isfinite(value) else "no source"):
            fail(f"observer {row[0]}: UGR {row[1]}, the file holds {value}")
    if len(table["rows"]) != len(ugr):
        fail("the observers' table has not one row per observer")


def ugr_shown(value):
    return f"{value:.1f}" if np.isfinite(value) else "no source"


def check_glare_grids(tables, h5):
    """Each glare grid's row against /glare_grids/<name>, its positions' table against the
    largest UGR over the views at each position, derived here from the dataset."""
    for k, row in enumerate(tables["glare-grids"]["rows"]):
        name = row[0]
        g = h5[f"glare_grids/{name}"]
        ugr = np.asarray(g["ugr"])
        nv, nu, views = ugr.shape
        if row[1] != f"{nu} × {nv} × {views}":
            fail(f"glare grid {name}: shows {row[1]}, the file holds {ugr.shape}")
        largest = g.attrs["UGR_max"]
        if row[4] != ugr_shown(largest) or largest != ugr.max():
            fail(f"glare grid {name}: UGR_max shows {row[4]}, the file holds {largest}, its largest {ugr.max()}")
        u, v = (int(x) for x in g.attrs["UGR_max_position"])
        if not row[5].startswith(f"({u}, {v}, ") or ugr[v, u].max() != largest:
            fail(f"glare grid {name}: the largest at {row[5]}, the file at ({u}, {v})")
        limit = g.attrs.get("ugr_limit")
        same(row[6], limit if limit is not None else np.nan, 0, f"glare grid {name} UGR_L")
        feeds = text(g.attrs.get("grid", "—"))
        if row[9] != feeds:
            fail(f"glare grid {name}: counts towards the grid {row[9]}, the file says {feeds}")
        per_position = ugr.max(axis=2)
        if limit is not None:
            expected = "yes" if largest <= limit else "no"
            above = f"{int((per_position > limit).sum())} of {nu * nv}"
            if row[7] != expected or row[8] != above:
                fail(f"glare grid {name}: within UGR_L {row[7]}, above {row[8]}; expected {expected}, {above}")
        positions = tables.get(f"glare-grid-{k + 1}")
        if positions is None:
            fail(f"glare grid {name}: no table of its positions")
        got = [r[1:] for r in positions["rows"]]
        expected = [[ugr_shown(x) for x in per_position[b]] for b in range(nv)]
        if got != expected:
            fail(f"glare grid {name}: its positions' table differs from the file: {got} against {expected}")


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def check_grid_ugr(h5, prefix=""):
    """Each grid's UGR under `prefix` the largest of its observers' and glare grids' readings."""
    if f"{prefix}grids" not in h5:
        return
    names = [text(n) for n in h5[f"{prefix}observers/grid"][()]] if f"{prefix}observers/grid" in h5 else []
    observed = np.asarray(h5[f"{prefix}observers/ugr"]) if names else np.zeros(0)
    glare = h5.get(f"{prefix}glare_grids", {})
    for grid, g in h5[f"{prefix}grids"].items():
        readings = [observed[i] for i, n in enumerate(names) if n == grid]
        readings += [x for k in glare if text(glare[k].attrs.get("grid", "")) == grid for x in np.ravel(glare[k]["ugr"])]
        ugr = g.attrs.get("UGR")
        if not readings:
            if ugr is not None:
                fail(f"/{prefix}grids/{grid}: UGR {ugr}, but no observer or glare grid names it")
            continue
        if ugr is None or ugr != max(readings):
            fail(f"/{prefix}grids/{grid}: UGR {ugr}, the largest of its observers and glare grids {max(readings)}")


def check_light_scenes(table, h5):
    grid = table["head"].index("grid")
    observers = [text(n) for n in h5["observers/name"]] if "observers/name" in h5 else []
    limits = np.asarray(h5["observers/ugr_limit"]) if observers else []
    for row, classes in zip(table["rows"], table["classes"]):
        if row[grid] != "—":
            check_stats(row[grid + 1:grid + 10], h5[f"light_scenes/{row[0]}/grids/{row[grid]}"].attrs, f"light scene {row[0]}")
        ugrs = np.asarray(h5[f"light_scenes/{row[0]}/observers/ugr"]) if observers else []
        for k, (name, value, limit) in enumerate(zip(observers, ugrs, limits)):
            column = table["head"].index(f"UGR {name}")
            if row[column] != ugr_shown(value):
                fail(f"light scene {row[0]}, observer {name}: UGR {row[column]}, the file holds {value}")
            met = None if not np.isfinite(limit) else ("pass" if not np.isfinite(value) or value <= limit else "fail")
            if classes[column] != met:
                fail(f"light scene {row[0]}, observer {name}: UGR {value} against UGR_L {limit} shown as {classes[column]}")


def check_probes(table, h5):
    """Each probe's illuminance with its bar, direct part and luminance, and its illuminance
    with its bar in each light scene, as /probes and /light_scenes/<name>/probes hold them."""
    names = [text(n) for n in h5["probes/name"]]
    if [row[0] for row in table["rows"]] != names:
        fail(f"the probes' table lists {[row[0] for row in table['rows']]}, the file {names}")
    scenes = [text(s) for s in h5["light_groups/scene_names"]] if "light_groups/scene_names" in h5 else []
    head = ["probe", "kind", "illuminance (lx)", "of it direct (lx)", "luminance (cd/m²)"]
    head += [f"illuminance in {s} (lx)" for s in scenes]
    if table["head"] != head:
        fail(f"the probes' table's header {table['head']}, expected {head}")

    def with_bar(at, i):
        value = shown(h5[f"{at}/illuminance"][i], 1)
        bar = h5[f"{at}/error"][i] if f"{at}/error" in h5 else np.nan
        return f"{value} ± {bar:.1f}" if np.isfinite(bar) and value != "—" else value

    for i, row in enumerate(table["rows"]):
        expected = [with_bar("probes", i), shown(h5["probes/direct"][i], 1), shown(h5["probes/luminance"][i], 2)]
        expected += [with_bar(f"light_scenes/{s}/probes", i) for s in scenes]
        if row[2:] != expected:
            fail(f"probe {row[0]}: the page shows {row[2:]}, the file holds {expected}")


def main():
    page_path, h5_path = sys.argv[1], sys.argv[2]
    page = Page()
    with open(page_path, encoding="utf-8") as f:
        page.feed(f.read())
    page.close()
    if not page.doctype:
        fail("no <!DOCTYPE html>")
    if page.stack:
        fail(f"unclosed tags at the end: {page.stack}")
    for name, table in page.tables.items():
        width = len(table["head"])
        for row in table["rows"]:
            if len(row) != width:
                fail(f"table {name}: a row of {len(row)} cells under a header of {width}: {row}")
    if not page.images:
        fail("no plan in the page")
    for src in page.images:
        check_png(src)
    with h5py.File(h5_path, "r") as h5:
        checks = {
            "grids": check_grids,
            "luminaires": check_luminaires,
            "surfaces": check_surfaces,
            "daylight-grids": check_daylight,
            "observers": check_observers,
            "light-scenes": check_light_scenes,
            "probes": check_probes,
        }
        for name, check in checks.items():
            if name in page.tables:
                check(page.tables[name], h5)
        if "glare-grids" in page.tables:
            check_glare_grids(page.tables, h5)
        check_grid_ugr(h5)
        for scene in h5.get("light_scenes", {}):
            check_grid_ugr(h5, f"light_scenes/{scene}/")
        missing = [n for n in ("grids", "luminaires", "surfaces") if n not in page.tables]
        if missing:
            fail(f"no table {missing}")
    print(f"report_check: ok ({len(page.tables)} tables, {len(page.images)} plans: {', '.join(page.tables)})")


main()
