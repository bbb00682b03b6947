//! The hierarchy's build tells its stages: the direct light on the roots (the daylit
//! office's window on every root; the building floor's 29 windows made it minutes of
//! silence) is announced with the number of roots and advances once per root.

use std::path::Path;
use std::sync::Mutex;
use ugo::model::Model;
use ugo::progress::Progress;
use ugo::scene::{Hierarchical, KernelKind, Scene};

/// Each stage begun, with its announced total and the units it advanced.
#[derive(Default)]
struct Stages(Mutex<Vec<(String, u64, u64)>>);

impl Progress for Stages {
    fn begin(&self, what: &str, total: u64) {
        self.0.lock().unwrap().push((what.to_string(), total, 0));
    }
    fn advance(&self, done: u64) {
        self.0.lock().unwrap().last_mut().expect("a stage begun").2 += done;
    }
    fn at(&self, _: u64, _: &str) {}
    fn end(&self) {}
}

#[test]
fn the_direct_light_on_the_roots_advances_root_by_root() {
    let mut scene = Scene::load(Path::new("cases/daylit-office.toml")).unwrap();
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical { root_size: 1.0, link_tolerance: 1e-1 });
    scene.discretization.patch_size = 0.5;
    let stages = Stages::default();
    let model = Model::build(&scene, &stages).expect("fits in memory");
    let stages = stages.0.into_inner().unwrap();
    let roots = model.hierarchy.as_ref().expect("hierarchical").roots as u64;
    let seed = stages.iter().find(|s| s.0 == "direct light on the roots").expect("the stage is announced");
    assert!(roots > 10, "{roots} roots");
    assert_eq!((seed.1, seed.2), (roots, roots), "announced and advanced per root");
}
