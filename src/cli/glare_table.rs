//! `ugo glare --table LUMINAIRE [--csv FILE] [--spacing R]`: the UGR table of CIE 190 of
//! an IES or EULUMDAT luminaire (`ugo::readout::ugr_table`, `docs/photometry.md`, "The
//! UGR table"), printed as the catalogues print it, with the conditions it holds under.

use super::check_writable;
use anyhow::{Result, bail};
use std::path::{Path, PathBuf};
use ugo::photometry::{Distribution, IntensityDistribution, LuminousOpening, read_ies, read_ldt};
use ugo::readout::standard_room::Viewing;
use ugo::readout::ugr::VALID_SOLID_ANGLE;
use ugo::readout::ugr_table::{HEIGHT, REFERENCE_FLUX, REFLECTANCES, ROOMS, UgrTable, ugr_table};

/// The UGR scale of CIE 117 the table's values are judged on.
const SCALE: [f64; 2] = [10.0, 30.0];

pub fn run(luminaire: &Path, csv: Option<PathBuf>, spacing: f64) -> Result<()> {
    if !(spacing > 0.0 && spacing <= 2.0) {
        bail!("--spacing must be a spacing-to-height ratio in (0, 2], got {spacing}");
    }
    if let Some(path) = &csv {
        check_writable(path)?;
    }
    let file = read(luminaire)?;
    let Some(opening) = file.luminous else {
        bail!(
            "{}: the file sizes no luminous area, so the luminance I/A the UGR needs is undefined: \
             give the file its luminous area",
            luminaire.display()
        );
    };
    let (flux, whence) = match file.lamp_flux {
        Some(f) => (f, "the file's lamps"),
        None => (file.flux(), "absolute photometry: the luminaire's own, integrated"),
    };
    let table = ugr_table(&Distribution::Table(Box::new(file)), flux, spacing);
    print_conditions(luminaire, &opening, &table, whence);
    print_table(&table);
    print_validity(&table);
    if let Some(path) = csv {
        ugo::io::write_ugr_table_csv(&path, &table)?;
        say!("written {}", path.display());
    }
    Ok(())
}

/// The file by its extension.
fn read(path: &Path) -> Result<IntensityDistribution> {
    let extension = path.extension().map(|e| e.to_string_lossy().to_lowercase());
    Ok(match extension.as_deref() {
        Some("ies") => read_ies(path)?,
        Some("ldt") => read_ldt(path)?,
        _ => bail!("{}: a luminaire is an IES (.ies) or EULUMDAT (.ldt) file", path.display()),
    })
}

fn print_conditions(luminaire: &Path, opening: &LuminousOpening, table: &UgrTable, whence: &str) {
    say!("UGR table of {} (CIE 190:2010 tabular method, CIE 117:1995 formula)", luminaire.display());
    say!("  luminous area: {}", shown(opening));
    say!(
        "  rooms X × Y in multiples of H, the luminaires' height above the eye (H = {HEIGHT} m; the UGR does \
         not depend on it); spacing-to-height ratio {}; the eye at the middle of a wall looking horizontally \
         across the room",
        table.spacing
    );
    say!(
        "  table for {REFERENCE_FLUX} lm of lamp flux; the lamps give {:.1} lm ({whence}): add 8 log10(Φ/{REFERENCE_FLUX}) \
         = {:+.2}",
        table.flux,
        table.summand()
    );
}

fn print_table(table: &UgrTable) {
    let row = |what: &str, value: &dyn Fn(usize) -> f64| {
        let values: Vec<String> = (0..10).map(|k| format!("{:5.2}", value(k % 5))).collect();
        say!("{what:<14}{}    {}", values[..5].join(" "), values[5..].join(" "));
    };
    row("ceiling", &|k| REFLECTANCES[k].ceiling);
    row("walls", &|k| REFLECTANCES[k].walls);
    row("floor", &|k| REFLECTANCES[k].floor);
    let [across, along] = Viewing::BOTH.map(Viewing::name);
    say!("room X × Y     {:<33}viewed {along}", format!("viewed {across}"));
    for (i, [x, y]) in ROOMS.iter().enumerate() {
        let cells = &table.cells[i * 10..(i + 1) * 10];
        let values: Vec<String> = cells.iter().map(|c| format!("{:5.1}", c.ugr - table.summand())).collect();
        say!("{:<14}{}    {}", format!("{x}H {y}H"), values[..5].join(" "), values[5..].join(" "));
    }
}

fn print_validity(table: &UgrTable) {
    let [low, high] = table.solid_angles;
    let [least, most] = VALID_SOLID_ANGLE;
    let holds = if low > least && high < most { "within" } else { "NOT all within" };
    say!(
        "  the luminaires counted subtend {low:.2e} to {high:.2e} sr at H = {HEIGHT} m: {holds} the {least}–{most} sr \
         where CIE 117's formula holds"
    );
    let outside = table.cells.iter().filter(|c| !(SCALE[0]..=SCALE[1]).contains(&(c.ugr - table.summand()))).count();
    if outside > 0 {
        say!("  {outside} of the {} values lie outside CIE 117's scale {}–{}", table.cells.len(), SCALE[0], SCALE[1]);
    }
}

/// The opening in words, mm.
fn shown(opening: &LuminousOpening) -> String {
    let mm = |m: f64| m * 1000.0;
    match *opening {
        LuminousOpening::Box { length, width, height } => {
            format!("{:.0} × {:.0} mm (C0 × C90), {:.0} mm high", mm(length), mm(width), mm(height))
        }
        LuminousOpening::Cylinder { diameter, height } => {
            format!("disc of {:.0} mm, {:.0} mm high", mm(diameter), mm(height))
        }
        LuminousOpening::Sphere { diameter } => format!("sphere of {:.0} mm", mm(diameter)),
    }
}
