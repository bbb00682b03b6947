//! `ugo solve --part i/n` and `ugo parts` (issue 36, point 4): the parts of one case join
//! and count the one-process linking's links; bad parts, another case's part, a missing
//! or doubled part and the uniform kernel are refused by name; a saved hierarchy's
//! `leaves/root_position` gives every leaf the part `--part i/n` puts its root in.

use super::{assert_clean_failure, stderr};
use crate::support::{scratch, ugo};
use std::path::Path;
use ugo::kernel::hierarchy::part_of;

const COARSE: [&str; 6] = ["--kernel", "hierarchical", "--root-size", "0.4", "--patch-size", "0.1"];

/// Links part `part` of `case` at the coarse settings into `out`.
fn link(case: &str, part: &str, out: &Path) -> std::process::Output {
    let mut args = vec!["solve", case, "--part", part, "-o", out.to_str().unwrap()];
    args.extend(COARSE);
    ugo(&args)
}

/// The total links `ugo parts` prints for `files`.
fn joined(files: &[&Path]) -> usize {
    let mut args = vec!["parts"];
    args.extend(files.iter().map(|f| f.to_str().unwrap()));
    let o = ugo(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    let line = out.lines().find(|l| l.contains("parts of one case and partition")).expect("a total line");
    line.split(": ").nth(1).and_then(|t| t.split(' ').next()).and_then(|n| n.parse().ok()).expect("a count")
}

#[test]
fn parts_join_into_as_many_links_as_one_part() {
    let dir = scratch("parts");
    let case = "cases/cornell-box.toml";
    let (whole, a, b) = (dir.join("whole.h5"), dir.join("a.h5"), dir.join("b.h5"));
    for (part, out) in [("0/1", &whole), ("0/2", &a), ("1/2", &b)] {
        let o = link(case, part, out);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(String::from_utf8_lossy(&o.stdout).contains("cut links"));
    }
    assert_eq!(joined(&[&a, &b]), joined(&[&whole]), "two parts hold the one-process links");
    let err = assert_clean_failure(&ugo(&["parts", a.to_str().unwrap()]));
    assert!(err.contains("parts 1 of 2 are missing"), "{err}");
    let err = assert_clean_failure(&ugo(&["parts", a.to_str().unwrap(), a.to_str().unwrap()]));
    assert!(err.contains("are both part 0/2"), "{err}");
    let err = assert_clean_failure(&ugo(&["parts", a.to_str().unwrap(), whole.to_str().unwrap()]));
    assert!(err.contains("different partitions"), "{err}");
    let other = dir.join("other.h5");
    assert!(link("cases/furnace-box.toml", "1/2", &other).status.success());
    let err = assert_clean_failure(&ugo(&["parts", a.to_str().unwrap(), other.to_str().unwrap()]));
    assert!(err.contains("different cases: geometry"), "{err}");
}

#[test]
fn bad_parts_and_the_uniform_kernel_are_refused() {
    let dir = scratch("parts-bad");
    let out = dir.join("p.h5");
    for (part, says) in [("2/2", "below the number of parts"), ("0/0", "at least 1"), ("1:2", "expected i/n")] {
        let o = link("cases/cornell-box.toml", part, &out);
        let err = stderr(&o);
        assert!(!o.status.success() && err.contains(says), "{part}: {err}");
    }
    let o = ugo(&["solve", "cases/cornell-box.toml", "--kernel", "uniform", "--part", "0/2"]);
    let err = assert_clean_failure(&o);
    assert!(err.contains("the case's kernel is uniform"), "{err}");
    let mut args = vec!["solve", "cases/cornell-box.toml", "--part", "0/2", "--method", "gmres"];
    args.extend(COARSE);
    let err = assert_clean_failure(&ugo(&args));
    assert!(err.contains("does not solve"), "{err}");
}

/// `(leaf_node, root_position, parent, level)` of a saved hierarchy's `/kernel/hierarchy`.
fn saved_leaves(path: &Path) -> (Vec<u32>, Vec<u32>, Vec<u32>, Vec<u8>) {
    let f = hdf5::File::open(path).unwrap();
    let read = |name: &str| f.dataset(&format!("kernel/hierarchy/{name}")).unwrap();
    let u32s = |name: &str| read(name).read_raw::<u32>().unwrap();
    (u32s("tree/leaf_node"), u32s("leaves/root_position"), u32s("tree/parent"), read("tree/level").read_raw().unwrap())
}

#[test]
fn a_saved_hierarchy_gives_every_leaf_the_part_of_its_root() {
    let dir = scratch("parts-of-leaves");
    let case = "cases/cornell-box.toml";
    let saved = dir.join("saved.h5");
    let mut args = vec!["solve", case, "--save-kernel", "-o", saved.to_str().unwrap()];
    args.extend(COARSE);
    let o = ugo(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let (leaf_node, position, parent, level) = saved_leaves(&saved);
    let again = dir.join("again.h5");
    let mut args =
        vec!["solve", case, "--kernel-file", saved.to_str().unwrap(), "--save-kernel", "-o", again.to_str().unwrap()];
    args.extend(COARSE);
    assert!(ugo(&args).status.success(), "a reused hierarchy saved again");
    assert_eq!(saved_leaves(&again).1, position, "the roots' positions read back and written again");
    let root = |mut id: u32| {
        while level[id as usize] != 0 {
            id = parent[id as usize];
        }
        id
    };
    let roots = level.iter().filter(|&&l| l == 0).count();
    assert!(position.windows(2).all(|w| w[0] <= w[1]), "the leaves, depth first, run through the roots in order");
    for count in [2u32, 3] {
        let mut part_of_root = vec![u32::MAX; roots];
        for index in 0..count {
            let out = dir.join(format!("p{index}-{count}.h5"));
            assert!(link(case, &format!("{index}/{count}"), &out).status.success());
            let own: Vec<u32> = hdf5::File::open(&out).unwrap().dataset("part/roots").unwrap().read_raw().unwrap();
            own.iter().for_each(|&r| part_of_root[r as usize] = index);
        }
        for (&leaf, &p) in leaf_node.iter().zip(&position) {
            assert_eq!(
                part_of(p, roots, count),
                part_of_root[root(leaf) as usize],
                "leaf node {leaf} of {count} parts"
            );
        }
    }
}
