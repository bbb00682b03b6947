//! The UGR table of CIE 190 (`ugo::readout::ugr_table`, `docs/photometry.md`, "The UGR
//! table", issue 38 point 1): its transfer factors against CIE 190's Table 5, one cell of a
//! Lambertian panel against a calculation by hand from first principles, its background
//! and its UGR against ugo's own radiosity solve of the standard room and the UGR read
//! there by an `[[observer]]`, and `ugo glare --table`.

use crate::support::{arriving, build, corner_factor, mean_over, scratch, solve};
use glam::DVec3;
use std::f64::consts::PI;
use std::path::Path;
use ugo::geometry::ConvexPolygon;
use ugo::photometry::{Distribution, parse_ies};
use ugo::readout::cavity::{Cavity, Reflectances};
use ugo::readout::standard_room::Viewing;
use ugo::readout::ugr::unified_glare_rating;
use ugo::readout::ugr_table::{HEIGHT, REFLECTANCES, ROOMS, UgrTable, ugr_table};
use ugo::scene::Scene;
use ugo::transfer::contour::point_to_polygon;

/// A flat 0.6 × 0.6 m Lambertian panel of 1000 lm (`I = (1000/π) cos γ`, 1° steps), one lamp of 1000 lm.
fn panel() -> String {
    let gammas: Vec<String> = (0..=90).map(|g| g.to_string()).collect();
    let candela: Vec<String> =
        (0..=90).map(|g| format!("{:.9}", 1000.0 / PI * f64::from(g).to_radians().cos())).collect();
    format!(
        "IESNA:LM-63-2002\n[TEST] lambertian panel\nTILT=NONE\n1 1000 1 91 1 1 2 0.6 0.6 0\n1 1 0\n{}\n0\n{}\n",
        gammas.join(" "),
        candela.join(" ")
    )
}

fn table_of_panel(spacing: f64) -> UgrTable {
    let file = parse_ies(Path::new("panel.ies"), &panel()).expect("a valid file");
    ugr_table(&Distribution::Table(Box::new(file)), 1000.0, spacing)
}

/// CIE 190's Table 5 at `k = 2.67` (4H × 8H), `F_T,FW`, `F_T,WW−1`, `F_T,CW` for the five
/// combinations, as eulumdat-ugr (github.com/123VincentB/eulumdat-ugr, background.py) quotes it.
const TABLE_5: [[f64; 3]; 5] =
    [[0.115, 0.211, 0.307], [0.106, 0.117, 0.283], [0.100, 0.187, 0.211], [0.093, 0.104, 0.196], [0.081, 0.092, 0.114]];

#[test]
fn the_transfer_factors_are_cie_190s_table_5() {
    let cavity = Cavity { width: 8.0, depth: 16.0, height: 2.0 };
    assert!((cavity.room_index() - 8.0 / 3.0).abs() < 1e-12);
    for (rho, published) in REFLECTANCES.iter().zip(TABLE_5) {
        let t = cavity.transfer(*rho);
        for (ours, theirs) in [t.floor, t.walls, t.ceiling].into_iter().zip(published) {
            // Table 5 gives three decimals.
            assert!((ours - theirs).abs() <= 5.01e-4, "{rho:?}: {ours:.5} against {theirs}");
        }
    }
}

/// The floor-to-ceiling form factor by ugo's contour integral averaged over the floor, and
/// the interreflection by its Neumann series: independent of `cavity.rs`'s closed form and
/// Cramer's rule.
fn transfer_by_hand(x: f64, y: f64, h: f64, rho: Reflectances) -> [f64; 3] {
    let ceiling =
        ConvexPolygon::quad(DVec3::new(0.0, h, 0.0), DVec3::new(x, h, 0.0), DVec3::new(x, h, y), DVec3::new(0.0, h, y));
    let across = mean_over((0.0, x), (0.0, y), 16, |a, b| point_to_polygon(DVec3::new(a, 0.0, b), DVec3::Y, &ceiling));
    let (floor_area, wall_area) = (x * y, 2.0 * h * (x + y));
    let from_walls = floor_area * (1.0 - across) / wall_area;
    let f =
        [[0.0, 1.0 - across, across], [from_walls, 1.0 - 2.0 * from_walls, from_walls], [across, 1.0 - across, 0.0]];
    let rho = [rho.floor, rho.walls, rho.ceiling];
    let mut out = [0.0; 3];
    for (first, wall) in out.iter_mut().enumerate() {
        let mut landed = [0.0; 3];
        landed[first] = 1.0;
        for _ in 0..400 {
            let next: Vec<f64> = (0..3).map(|i| (0..3).map(|j| landed[j] * rho[j] * f[j][i]).sum()).collect();
            *wall += next[1];
            landed = [next[0], next[1], next[2]];
        }
    }
    out
}

/// The UGR of the 1000 lm Lambertian panel in room `[x, y]` (multiples of H = 2 m) at
/// spacing 0.25 H under `rho`, from first principles.
fn by_hand(x: f64, y: f64, rho: Reflectances) -> f64 {
    let (h, s) = (2.0, 0.5);
    let (width, depth) = (x * h, y * h);
    let (nx, ny) = ((width / s).round() as usize, (depth / s).round() as usize);
    let (peak, area) = (1000.0 / PI, 0.36);
    let (mut sum, mut floor) = (0.0, 0.0);
    for j in 0..ny {
        for i in 0..nx {
            let (t, r) = ((i as f64 + 0.5) * s - width / 2.0, (j as f64 + 0.5) * s);
            let d2 = t * t + h * h + r * r;
            let d = d2.sqrt();
            // A flat Lambertian panel shines at I0/A from every direction below it.
            let cos_gamma = h / d;
            let (luminance, omega) = (peak * cos_gamma / (area * cos_gamma), area * cos_gamma / d2);
            let sigma = (r / d).acos().to_degrees();
            let tau = t.abs().atan2(h).to_degrees();
            let ln_p = (35.2 - 0.31889 * tau - 1.22 * (-2.0 * tau / 9.0).exp()) * 1e-3 * sigma
                + (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma;
            if t.abs() <= 3.0 * r {
                sum += luminance * luminance * omega / (2.0 * ln_p).exp();
            }
            // Its flux on the floor below: the four corner rectangles around its foot.
            let (x0, x1, z0, z1) = (-width / 2.0 - t, width / 2.0 - t, -r, depth - r);
            let g = |a: f64, b: f64| a.signum() * b.signum() * corner_factor(a.abs(), b.abs(), h);
            floor += 1000.0 * (g(x1, z1) - g(x0, z1) - g(x1, z0) + g(x0, z0));
        }
    }
    let n = (nx * ny) as f64;
    let floor = floor / n;
    let [ff, fw, _] = transfer_by_hand(width, depth, h, rho);
    let background = n * (floor * ff + (1000.0 - floor) * fw) / (2.0 * h * (width + depth)) / PI;
    8.0 * (0.25 / background * sum).log10()
}

#[test]
fn a_lambertian_panels_cells_match_the_hand_calculation() {
    let table = table_of_panel(0.25);
    assert!(table.summand().abs() < 1e-12, "1000 lm lamps need no summand");
    for (room, viewing, rho) in [(10, 0, 0), (10, 1, 4), (0, 0, 2), (18, 1, 1)] {
        let [x, y] = ROOMS[room];
        let cell = table.cells[room * 10 + viewing * 5 + rho];
        assert_eq!((cell.room, cell.viewing, cell.reflectances), ([x, y], Viewing::BOTH[viewing], REFLECTANCES[rho]));
        let expected = by_hand(x, y, REFLECTANCES[rho]);
        eprintln!("{x}H × {y}H {:?} {:?}: UGR {:.4}, by hand {expected:.4}", cell.viewing, cell.reflectances, cell.ugr);
        assert!((cell.ugr - expected).abs() < 1e-3, "UGR {} against {expected} by hand", cell.ugr);
    }
}

#[test]
fn doubling_the_flux_adds_8_log10_2_and_leaves_the_reference_table() {
    let file = parse_ies(Path::new("panel.ies"), &panel()).expect("a valid file");
    let one = ugr_table(&Distribution::Table(Box::new(file.clone())), 1000.0, 0.25);
    let mut brighter = file;
    brighter.scale(2.0);
    let two = ugr_table(&Distribution::Table(Box::new(brighter)), 2000.0, 0.25);
    for (a, b) in one.cells.iter().zip(&two.cells) {
        assert!((b.ugr - a.ugr - 8.0 * 2f64.log10()).abs() < 1e-9, "{} against {}", b.ugr, a.ugr);
        assert!(((b.ugr - two.summand()) - (a.ugr - one.summand())).abs() < 1e-9);
    }
}

/// The standard room 2H × 2H (4 × 4 m, H = 2 m) at spacing 0.25 H as a case: the reference
/// plane at `y = 0`, 64 panels just under the ceiling, an observer at the middle of the wall `z = 0`.
fn standard_room_case(rho: Reflectances) -> String {
    let (w, h) = (4.0, HEIGHT);
    let mut text = String::from("[discretization]\npatch_size = 0.25\n");
    for (name, r) in [("floor", rho.floor), ("walls", rho.walls), ("ceiling", rho.ceiling)] {
        text += &format!("[[material]]\nname = \"{name}\"\ntype = \"lambert\"\nreflectance = {r}\n");
    }
    let rectangles = [
        ("floor", "floor", [0.0, 0.0, 0.0], [0.0, 0.0, w], [w, 0.0, 0.0]),
        ("ceiling", "ceiling", [0.0, h, 0.0], [w, 0.0, 0.0], [0.0, 0.0, w]),
        ("eye wall", "walls", [0.0, 0.0, 0.0], [w, 0.0, 0.0], [0.0, h, 0.0]),
        ("far wall", "walls", [0.0, 0.0, w], [0.0, h, 0.0], [w, 0.0, 0.0]),
        ("left wall", "walls", [0.0, 0.0, 0.0], [0.0, h, 0.0], [0.0, 0.0, w]),
        ("right wall", "walls", [w, 0.0, 0.0], [0.0, 0.0, w], [0.0, h, 0.0]),
    ];
    for (name, material, origin, u, v) in rectangles {
        text += &format!(
            "[[surface]]\nname = \"{name}\"\nshape = \"rectangle\"\nmaterial = \"{material}\"\norigin = {origin:?}\n\
             edge_u = {u:?}\nedge_v = {v:?}\n"
        );
    }
    for j in 0..8 {
        for i in 0..8 {
            let (x, z) = ((i as f64 + 0.5) * 0.5, (j as f64 + 0.5) * 0.5);
            text += &format!(
                "[[luminaire]]\nname = \"panel {i} {j}\"\ntype = \"ies\"\nfile = \"panel.ies\"\nposition = [{x}, {}, {z}]\n",
                h - 1e-3
            );
        }
    }
    text + "[[observer]]\nname = \"eye\"\nposition = [2, 0.01, 0.01]\nlook = [0, 0, 1]\n"
}

/// The table's background against the solved standard room (70/50/20): the three-surface
/// room's mean indirect illuminance of the walls is the solved one's; the observer's own
/// background in the solved room (the vertical indirect illuminance at the eye) is reported beside.
#[test]
fn the_tables_background_is_the_solved_rooms_mean_indirect_wall_illuminance() {
    let rho = REFLECTANCES[0];
    let dir = scratch("ugr-table-room");
    std::fs::write(dir.as_ref().join("panel.ies"), panel()).expect("writable");
    let path = dir.as_ref().join("room.toml");
    std::fs::write(&path, standard_room_case(rho)).expect("writable");
    let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let model = build(&scene);
    let x = solve(&model);
    let gx = arriving(&model, &x);
    let cells = model.kernel.cells();
    let walls: Vec<u32> =
        (0..scene.surfaces.len() as u32).filter(|&s| scene.surfaces[s as usize].name.ends_with("wall")).collect();
    let (mut flux, mut area) = (0.0, 0.0);
    for (i, p) in model.mesh.patches.iter().enumerate() {
        if walls.contains(&p.surface) {
            flux += p.area * PI * gx[i * cells..(i + 1) * cells].iter().sum::<f64>();
            area += p.area;
        }
    }
    let solved = flux / area;
    let table = table_of_panel(0.25);
    let cell = table.cells[0];
    assert_eq!((cell.room, cell.reflectances), ([2.0, 2.0], rho));
    let tabular = PI * cell.background;
    let field = ugo::readout::field::Field::from_unknowns(&x, cells);
    let eye = ugo::readout::ugr::read_observers(&scene.observers, &model, &field).remove(0);
    eprintln!(
        "E_WID {tabular:.3} lx (table) against {solved:.3} lx (solved walls' mean): {:+.4}; the eye's own L_b {:.3} \
         against the table's {:.3} cd/m²: {:+.4}",
        tabular / solved - 1.0,
        eye.background,
        cell.background,
        cell.background / eye.background - 1.0
    );
    assert!((tabular / solved - 1.0).abs() < 0.01, "{tabular} lx against {solved} lx");
    // The cell from first principles: the luminaires the solved room's eye sees (ugo's
    // observer: luminous openings, Guth index, obstruction), those within Guth's table
    // (T/R ≤ 3) as CIE 190 counts them, with the table's L_b: 0.03 apart, the eye being 1 cm
    // off the reference plane and the wall and the panels 1 mm under the ceiling; then all
    // of them with the eye's own L_b (14 % lower than E_WID/π: a point, not the walls' mean).
    let within_table = |name: &str| {
        let [i, j] = [1, 2].map(|k| name.split(' ').nth(k).unwrap().parse::<f64>().unwrap());
        let (t, r) = (((i + 0.5) * 0.5 - 2.0).abs(), (j + 0.5) * 0.5 - 0.01);
        t / r <= 3.0
    };
    let counted: Vec<_> = eye.sources.iter().filter(|s| within_table(&s.name)).cloned().collect();
    let by_eye = unified_glare_rating(&counted, cell.background);
    eprintln!(
        "UGR {:.3} (table) against {by_eye:.3} (the solved room's eye, {} of its {} luminaires within T/R ≤ 3, the \
         table's L_b), {:.3} (all, its own L_b)",
        cell.ugr,
        counted.len(),
        eye.sources.len(),
        eye.ugr()
    );
    assert!((by_eye - cell.ugr).abs() < 0.05, "UGR {} (table) against {by_eye} (the eye)", cell.ugr);
    assert!((eye.ugr() - cell.ugr).abs() < 0.6, "UGR {} (table) against {} (the eye, all)", cell.ugr, eye.ugr());
}

#[test]
fn ugo_glare_prints_the_table_and_its_conditions() {
    let dir = scratch("ugr-table-cli");
    let file = dir.as_ref().join("panel.ies");
    std::fs::write(&file, panel()).expect("writable");
    let csv = dir.as_ref().join("table.csv");
    let o = crate::support::ugo(&["glare", "--table", file.to_str().unwrap(), "--csv", csv.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success(), "{stdout}{}", String::from_utf8_lossy(&o.stderr));
    for words in ["600 × 600 mm", "spacing-to-height ratio 0.25", "+0.00", "sr at H = 2 m", "12H 8H"] {
        assert!(stdout.contains(words), "missing {words:?} in\n{stdout}");
    }
    let rows = std::fs::read_to_string(&csv).expect("written");
    assert_eq!(rows.lines().count(), 1 + 190);
    // A file that sizes no luminous area cannot be rated.
    let bare = dir.as_ref().join("bare.ies");
    std::fs::write(&bare, panel().replace("2 0.6 0.6 0", "2 0 0 0")).expect("writable");
    let o = crate::support::ugo(&["glare", "--table", bare.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success() && stderr.contains("no luminous area"), "{stderr}");
}
