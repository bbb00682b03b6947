//! The classes of hard probes and a placed probe: what each class means is decided in
//! `place.rs`; here are their names (`corner-5cm`, `underside`, …) and their order.

use glam::DVec3;

/// Distances of the corner and edge probes from their walls, cm.
pub const EDGES: [u8; 3] = [2, 5, 10];

/// Distances of the contact probes from the foot of what stands on a surface, cm.
pub const CONTACTS: [u8; 2] = [1, 3];

/// Where a probe stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Class {
    /// On a surface of the room's shell, this many cm from two other walls of the shell
    /// (a trihedral corner).
    Corner(u8),
    /// On a surface of the room's shell, this many cm from one other wall of it and
    /// farther from any other (a concave edge).
    Edge(u8),
    /// This many cm from a concave edge of which at least one face is not the shell's:
    /// the foot of a block, a leg, a panel or a cabinet on the floor or at a wall.
    Contact(u8),
    /// On a face looking down with another surface below it within 1 m, not the shell's
    /// (boards, seats, desks).
    Underside,
    /// On the shell's floor with a surface above it within 1 m (under furniture).
    Under,
    /// On a face with another facing it within 3 cm (books, panels).
    Gap,
    /// Where no light of the sources in front of the surface arrives directly.
    Umbra,
    /// Where part of it arrives (between 2 % and 98 % of the unshadowed direct light).
    Penumbra,
    /// Among the dimmest 5 % of the surfaces by a quick estimate of the illuminance.
    Dim,
    /// Away from every edge, fully lit: the control.
    Open,
}

impl Class {
    /// Every class, in the order of the output.
    pub fn all() -> Vec<Class> {
        let mut all: Vec<Class> = EDGES.iter().map(|&d| Class::Corner(d)).collect();
        all.extend(EDGES.iter().map(|&d| Class::Edge(d)));
        all.extend(CONTACTS.iter().map(|&d| Class::Contact(d)));
        all.extend([
            Class::Underside,
            Class::Under,
            Class::Gap,
            Class::Umbra,
            Class::Penumbra,
            Class::Dim,
            Class::Open,
        ]);
        all
    }

    /// As written in a probe's name: `corner-5cm`, `underside`, ….
    pub fn name(&self) -> String {
        match self {
            Class::Corner(d) => format!("corner-{d}cm"),
            Class::Edge(d) => format!("edge-{d}cm"),
            Class::Contact(d) => format!("contact-{d}cm"),
            Class::Underside => "underside".into(),
            Class::Under => "under".into(),
            Class::Gap => "gap".into(),
            Class::Umbra => "umbra".into(),
            Class::Penumbra => "penumbra".into(),
            Class::Dim => "dim".into(),
            Class::Open => "open".into(),
        }
    }

    /// The distance from the walls of a corner, edge or contact, m.
    pub fn distance(&self) -> Option<f64> {
        match self {
            Class::Corner(d) | Class::Edge(d) | Class::Contact(d) => Some(0.01 * *d as f64),
            _ => None,
        }
    }
}

/// A probe placed: its class, its number within the class, a point off its surface and the
/// surface's normal.
#[derive(Debug, Clone, PartialEq)]
pub struct Placed {
    /// Its class.
    pub class: Class,
    /// Its number within the class, from 0.
    pub number: usize,
    /// Where it reads, [`super::OFFSET`] in front of its surface, m.
    pub position: DVec3,
    /// The surface's unit normal: the receiving side.
    pub normal: DVec3,
}

impl Placed {
    /// The probe's name: its class and number, `corner-5cm/017`.
    pub fn name(&self) -> String {
        format!("{}/{:03}", self.class.name(), self.number)
    }
}
