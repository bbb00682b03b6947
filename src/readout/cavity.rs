//! The three-surface room of the tabular UGR (`docs/photometry.md`, "The UGR table"):
//! a rectangular cavity whose floor is the reference plane at eye height, whose ceiling is
//! the plane of the luminaires `H` above it and whose walls are the band between them,
//! each surface Lambertian and of one uniform exitance. It owns the transfer factors
//! `F_T,XW` of CIE 190: the flux the walls receive after one reflection or more per lumen
//! that first lands on surface `X`, from the exact form factors of the cavity and the
//! three-by-three interreflection (`docs/design.md` (5.8)),
//!
//! `Φ_j = Φ⁰_j + Σ_i ρ_i F_ij Φ_i`,   `F_T,XW = (Φ_W − Φ⁰_W) / Φ⁰_X` with `Φ⁰` one lumen on `X`.
//!
//! It knows nothing of luminaires (the direct shares are `ugr_table.rs`'s).

use std::f64::consts::PI;

/// The reflectances of the cavity's surfaces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reflectances {
    /// The ceiling (the plane of the luminaires).
    pub ceiling: f64,
    /// The walls between the two planes.
    pub walls: f64,
    /// The floor cavity, the reference plane at eye height.
    pub floor: f64,
}

/// A rectangular cavity, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cavity {
    /// Its width (across the line of sight in the UGR table).
    pub width: f64,
    /// Its depth (along the line of sight).
    pub depth: f64,
    /// Its height, the luminaires' `H` above the eye.
    pub height: f64,
}

/// The wall flux per lumen that first lands on each surface, reflections only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transfer {
    /// `F_T,FW`: from the floor.
    pub floor: f64,
    /// `F_T,WW−1`: from the walls, their own first landing left out.
    pub walls: f64,
    /// `F_T,CW`: from the ceiling.
    pub ceiling: f64,
}

impl Cavity {
    /// The wall band's area `2H(X + Y)`, m².
    pub fn wall_area(&self) -> f64 {
        2.0 * self.height * (self.width + self.depth)
    }

    /// The room index `k = XY / (H(X + Y))`.
    pub fn room_index(&self) -> f64 {
        self.width * self.depth / (self.height * (self.width + self.depth))
    }

    /// The transfer factors under `rho`.
    pub fn transfer(&self, rho: Reflectances) -> Transfer {
        let across = parallel_rectangles(self.width, self.depth, self.height);
        let to_walls = 1.0 - across;
        let from_walls = self.width * self.depth * to_walls / self.wall_area();
        // Form factors F[i][j] from i to j, in the order floor, walls, ceiling.
        let f = [[0.0, to_walls, across], [from_walls, 1.0 - 2.0 * from_walls, from_walls], [across, to_walls, 0.0]];
        let rho = [rho.floor, rho.walls, rho.ceiling];
        let reflected = |first: usize| {
            let mut system = [[0.0; 3]; 3];
            for (j, row) in system.iter_mut().enumerate() {
                for (i, a) in row.iter_mut().enumerate() {
                    *a = f64::from(u8::from(i == j)) - rho[i] * f[i][j];
                }
            }
            let mut landed = [0.0; 3];
            landed[first] = 1.0;
            let total = solve3(system, landed);
            total[1] - landed[1]
        };
        Transfer { floor: reflected(0), walls: reflected(1), ceiling: reflected(2) }
    }
}

/// The form factor between two directly opposed parallel `a × b` rectangles `c` apart
/// (Howell's catalogue, C-11).
pub fn parallel_rectangles(a: f64, b: f64, c: f64) -> f64 {
    let (x, y) = (a / c, b / c);
    let (x1, y1) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
    let log = ((1.0 + x * x) * (1.0 + y * y) / (1.0 + x * x + y * y)).sqrt().ln();
    let sum = log + x * y1 * (x / y1).atan() + y * x1 * (y / x1).atan() - x * x.atan() - y * y.atan();
    2.0 / (PI * x * y) * sum
}

/// `A x = b` for a 3 × 3 system with a dominant diagonal (Cramer's rule).
fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let whole = det(a);
    let column = |k: usize| {
        let mut m = a;
        for (row, value) in m.iter_mut().zip(b) {
            row[k] = value;
        }
        det(m) / whole
    };
    [column(0), column(1), column(2)]
}
