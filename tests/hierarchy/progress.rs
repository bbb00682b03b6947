//! The hierarchy's build tells its stages: the direct light on the roots (the daylit
//! office's window on every root; the building floor's 29 windows made it minutes of
//! silence) is announced with the number of roots and advances once per root; the linking
//! (the building's first pass: nine minutes without a line) tells the pairs it settles, and
//! the leaves' direct light the leaves done, and each operator's push the leaves whose rows are
//! made.

use std::path::Path;
use std::sync::Mutex;
use ugo::model::Model;
use ugo::progress::Progress;
use ugo::scene::{Hierarchical, KernelKind, Scene};

/// Each stage begun, with its announced total and the units it advanced; and every
/// position told, with its message.
#[derive(Default)]
struct Stages(Mutex<Vec<(String, u64, u64)>>, Mutex<Vec<(u64, String)>>);

impl Progress for Stages {
    fn begin(&self, what: &str, total: u64) {
        self.0.lock().unwrap().push((what.to_string(), total, 0));
    }
    fn advance(&self, done: u64) {
        self.0.lock().unwrap().last_mut().expect("a stage begun").2 += done;
    }
    fn at(&self, position: u64, message: &str) {
        self.1.lock().unwrap().push((position, message.to_string()));
    }
    fn end(&self) {}
}

/// `case` built hierarchically (roots of 1 m, links to 0.1, leaves of 1 m), with what it told.
fn built(case: &str) -> (Model, Stages) {
    let mut scene = Scene::load(Path::new(case)).unwrap();
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size: 1.0,
        link_tolerance: 1e-1,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    scene.discretization.patch_size = 1.0;
    let stages = Stages::default();
    let model = Model::build(&scene, &stages).expect("fits in memory");
    (model, stages)
}

#[test]
fn the_direct_light_on_the_roots_advances_root_by_root() {
    let (model, stages) = built("cases/daylit-office.toml");
    let stages = stages.0.into_inner().unwrap();
    let roots = model.hierarchy.as_ref().expect("hierarchical").roots as u64;
    let seed = stages.iter().find(|s| s.0 == "direct light on the roots").expect("the stage is announced");
    assert!(roots > 10, "{roots} roots");
    assert_eq!((seed.1, seed.2), (roots, roots), "announced and advanced per root");
}

#[test]
fn the_linking_tells_the_pairs_it_settles_round_by_round() {
    let (model, stages) = built("cases/office.toml");
    let told = stages.1.into_inner().unwrap();
    let history = &model.hierarchy.as_ref().expect("hierarchical").history;
    let linking: Vec<&(u64, String)> = told.iter().filter(|(_, m)| m.starts_with("linking, round ")).collect();
    assert!(linking.len() >= history.len(), "{} linking reports for {} passes", linking.len(), history.len());
    let solved: Vec<u64> = told.iter().filter(|(_, m)| m == "refinement: passes solved").map(|t| t.0).collect();
    assert_eq!(solved, (1..=history.len() as u64).collect::<Vec<_>>(), "one report per pass solved");
    let first_pass = told.iter().take_while(|(_, m)| m.starts_with("linking, round "));
    let settled: Vec<u64> = first_pass.map(|t| t.0).collect();
    assert!(settled.len() > 1 && settled.windows(2).all(|w| w[0] < w[1]), "pairs settled grow: {settled:?}");
    let light = told.iter().filter(|(_, m)| m.starts_with("direct light on ")).collect::<Vec<_>>();
    let (last, message) = light.last().expect("the leaves' direct light is told");
    assert_eq!(message, &format!("direct light on {last} new leaves: leaves done"), "every new leaf counted");
}

/// Each operator's push (minutes on the building's million leaves, silent before) tells
/// the leaves done, a batch at a time, up to all of them; one operator per pass.
#[test]
fn the_operators_push_tells_the_leaves_done() {
    let (model, stages) = built("cases/office.toml");
    let told = stages.1.into_inner().unwrap();
    let passes = model.hierarchy.as_ref().expect("hierarchical").history.len();
    let total = |m: &str| -> Option<u64> { m.strip_prefix("the operator's push on ")?.split(' ').next()?.parse().ok() };
    let push: Vec<(u64, u64)> = told.iter().filter_map(|(at, m)| Some((*at, total(m)?))).collect();
    assert!(push.iter().all(|(at, all)| at <= all), "never beyond the leaves: {push:?}");
    let complete = push.iter().filter(|(at, all)| at == all).count();
    assert!(complete >= passes, "{complete} operators told to the end for {passes} passes");
    assert_eq!(push.last().map(|p| p.1), Some(model.mesh.patches.len() as u64), "the last operator's leaves");
}
