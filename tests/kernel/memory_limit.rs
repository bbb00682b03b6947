//! The default memory limit (issue 37, point 7): half of the least of the machine's memory,
//! the control group's limit and the process's address space, so that `ulimit -v` or a
//! container's limit refuses a model with the figures instead of an allocation abort.

use std::process::Command;
use ugo::kernel::memory::{address_space_limit, cgroup_limit, physical_memory};

#[test]
fn the_limits_are_read_from_the_kernels_files() {
    assert_eq!(physical_memory("MemTotal:       24576000 kB\nMemFree: 1 kB\n"), Some(24_576_000 * 1024));
    assert_eq!(cgroup_limit("max\n"), None);
    assert_eq!(cgroup_limit("6442450944\n"), Some(6 << 30));
    let limits = "Limit                     Soft Limit           Hard Limit           Units     \n\
                  Max stack size            8388608              unlimited            bytes     \n\
                  Max address space         4294967296           unlimited            bytes     \n";
    assert_eq!(address_space_limit(limits), Some(4 << 30));
    assert_eq!(address_space_limit(&limits.replace("4294967296", "unlimited")), None);
}

#[test]
fn an_address_space_limit_halves_into_the_memory_limit() {
    // `ulimit -v` of 4 GiB (in KiB): the case's limit is 2 GiB, whatever the machine has
    let ugo = env!("CARGO_BIN_EXE_ugo");
    let script = format!("ulimit -v 4194304; exec {ugo} info cases/cornell-box.toml");
    let o = Command::new("sh").args(["-c", &script]).output().unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{out}{}", String::from_utf8_lossy(&o.stderr));
    let line = out.lines().find(|l| l.contains("memory limit")).unwrap_or_else(|| panic!("{out}"));
    assert!(line.ends_with("2.00 GiB"), "{line}");
}
