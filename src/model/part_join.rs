//! Joining part files (issue 36, point 4): parts of one case (equal fingerprints) and one
//! partition (equal part count and hash of every root's part), each part once and none
//! missing; anything else is refused naming the files and what differs.

use super::fingerprint::Fingerprint;
use super::part::PartLinks;

/// One part as read, with the name of its file for messages.
pub struct NamedPart<'a> {
    /// The file it was read from.
    pub name: String,
    /// The fingerprint of its case.
    pub fingerprint: &'a Fingerprint,
    /// Its links and counts.
    pub links: &'a PartLinks,
}

/// Why parts do not join.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum Unjoinable {
    /// No part given.
    #[error("no part files given")]
    None,
    /// Two parts of different cases.
    #[error("{0} and {1} were linked for different cases: {2} changed")]
    OtherCase(String, String, String),
    /// Two parts of different partitions.
    #[error("{0} and {1} belong to different partitions ({2}); link every part with the same --part i/n and case")]
    OtherPartition(String, String, String),
    /// A part given twice.
    #[error("{0} and {1} are both part {2}")]
    Twice(String, String, String),
    /// Parts missing.
    #[error("parts {0} of {1} are missing (ugo solve CASE --part i/{1} writes part i)")]
    Missing(String, u32),
}

/// Checks that `parts` are all the parts of one partition of one case; returns them in
/// part order.
pub fn join<'a, 'b>(parts: &'b [NamedPart<'a>]) -> Result<Vec<&'b NamedPart<'a>>, Unjoinable> {
    let first = parts.first().ok_or(Unjoinable::None)?;
    for p in &parts[1..] {
        let changes = p.fingerprint.changes_from(first.fingerprint);
        if !changes.is_empty() {
            let named: Vec<String> = changes.iter().map(|c| c.part.name().to_string()).collect();
            return Err(Unjoinable::OtherCase(first.name.clone(), p.name.clone(), named.join(", ")));
        }
        let (a, b) = (first.links, p.links);
        if a.part.count != b.part.count || a.roots != b.roots || a.partition != b.partition {
            let what = format!(
                "{} parts of {} roots against {} of {}, partition {:016x} against {:016x}",
                a.part.count, a.roots, b.part.count, b.roots, a.partition, b.partition
            );
            return Err(Unjoinable::OtherPartition(first.name.clone(), p.name.clone(), what));
        }
    }
    let count = first.links.part.count;
    let mut slots: Vec<Option<&NamedPart>> = vec![None; count as usize];
    for p in parts {
        let slot = &mut slots[p.links.part.index as usize];
        if let Some(other) = slot {
            return Err(Unjoinable::Twice(other.name.clone(), p.name.clone(), p.links.part.to_string()));
        }
        *slot = Some(p);
    }
    let missing: Vec<String> =
        slots.iter().enumerate().filter(|(_, s)| s.is_none()).map(|(i, _)| i.to_string()).collect();
    if !missing.is_empty() {
        return Err(Unjoinable::Missing(missing.join(", "), count));
    }
    Ok(slots.into_iter().flatten().collect())
}
