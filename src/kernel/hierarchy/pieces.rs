//! A link's factor by cells (`link.rs`), owned behind one thin pointer: none for the one
//! piece of `K = 1`, a boxed slice otherwise, so that a link spends 8 bytes on its pieces
//! where a `Vec` took 24 (issue 35, point 3).

use std::ops::Deref;

/// One piece of a factor: receiver cell `d`, source cell `m`, `F^{d,m}`.
pub type Piece = (u16, u16, f64);

/// The pieces of a link's factor, `(d, m, F^{d,m})`; empty means the one piece
/// `(0, 0, factor)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Pieces(Option<Box<Box<[Piece]>>>);

impl From<Vec<Piece>> for Pieces {
    fn from(pieces: Vec<Piece>) -> Pieces {
        Pieces((!pieces.is_empty()).then(|| Box::new(pieces.into_boxed_slice())))
    }
}

impl Deref for Pieces {
    type Target = [Piece];

    fn deref(&self) -> &[Piece] {
        self.0.as_deref().map_or(&[], |pieces| pieces)
    }
}
