//! The classroom of issue 37 (`cases/classroom.toml`: twelve EULUMDAT panels, 24 desks, a
//! whiteboard, a glazed window band under the overcast sky, the work plane at the desk
//! tops' height), coarsened to 0.5 m patches: it solves with no warning and no grid point
//! counted at zero.

use super::stderr;
use crate::support::{scratch, ugo};

#[test]
fn the_classroom_solves_with_no_warning_and_no_silent_zero() {
    let dir = scratch("classroom");
    let out = dir.join("classroom.h5");
    let o = ugo(&["solve", "cases/classroom.toml", "--patch-size", "0.5", "-o", out.to_str().unwrap()]);
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    // the one note is the size rule's: patches of 0.5 m take the hierarchy
    let notes: Vec<&str> = err.lines().filter(|l| l.starts_with("ugo: note")).collect();
    assert_eq!(notes.len(), 1, "{err}");
    assert!(notes[0].contains("no `kernel` in [discretization]: the hierarchical kernel"), "{err}");
    assert!(!err.contains("ugo: warning"), "{err}");
    let csv = std::fs::read_to_string(dir.join("classroom-work_plane.csv")).unwrap();
    assert!(csv.contains("over the 80 of 80 points counted"), "{csv}");
    let header = csv.lines().find(|l| l.starts_with("u,")).unwrap().split(',').collect::<Vec<_>>();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (e, counted) = (column("E_lx"), column("counted"));
    let rows = csv.lines().filter(|l| !l.starts_with('#') && !l.starts_with("u,"));
    for row in rows.map(|l| l.split(',').collect::<Vec<_>>()) {
        let lx: f64 = row[e].parse().unwrap();
        assert!(row[counted] != "1" || lx > 100.0, "a counted point at {lx} lx: {row:?}");
    }
}
