//! [`LawBuilder`], a law's `PROPS` array built by
//! entry name: for tests, scenes, fuzz decoders and harness generators, so that none of them
//! builds `PROPS` by position. Each law names its builder (`CoulombBuilder` is
//! `LawBuilder<LAW_COULOMB>`) and writes its setters, one per entry, with
//! [`entry_setters!`](entry_setters).

use super::LAYOUTS;
use super::schema::{Layout, PropsBuilder};

/// The layout of the law with code `law`. Panics (at compile time where it is a constant) on
/// a code no law has.
const fn layout_of(law: i32) -> &'static Layout {
    let mut i = 0;
    while i < LAYOUTS.len() {
        if LAYOUTS[i].code == law {
            return LAYOUTS[i];
        }
        i += 1;
    }
    panic!("no law has this PROPS(1) code")
}

/// The `PROPS` array of the law with code `LAW`, built by entry name: every entry starts at
/// its "0 / absent" value, `PROPS(1)` the law code. Each law's setters (one per entry, by its
/// key in the layout, so that an unknown key does not compile) are in the law's `props` file.
#[derive(Clone, Debug, PartialEq)]
pub struct LawBuilder<const LAW: i32>(PropsBuilder);

impl<const LAW: i32> LawBuilder<LAW> {
    /// The law's layout (a constant: a code no law has does not compile).
    pub(crate) const LAYOUT: &'static Layout = layout_of(LAW);

    /// Every entry at its "0 / absent" value, `PROPS(1)` the law code.
    #[must_use]
    pub fn new() -> Self {
        LawBuilder(PropsBuilder::new(Self::LAYOUT))
    }

    /// Sets `PROPS(index)` (the laws' named setters pass a constant index).
    #[must_use]
    pub(crate) fn set(self, index: usize, v: f64) -> Self {
        LawBuilder(self.0.set(index, v))
    }

    /// Every entry of the layout.
    #[must_use]
    pub fn build(&self) -> Vec<f64> {
        self.0.build()
    }

    /// The first `nprops` entries (a host that leaves out trailing ones).
    #[must_use]
    pub fn build_first(&self, nprops: usize) -> Vec<f64> {
        self.0.build_first(nprops)
    }
}

impl<const LAW: i32> Default for LawBuilder<LAW> {
    fn default() -> Self {
        Self::new()
    }
}

/// One setter per entry of a law's builder, inside `impl LawBuilder<LAW_…>`:
/// `entry_setters!("law 2", { coeff => "coeff", … })` writes, per pair, the documented
/// `pub fn coeff(self, v: f64) -> Self` that sets the entry whose key is `"coeff"` (its index
/// found when the crate compiles: an unknown key is a compile error). Each setter's name is
/// the identifier written at the invocation. A macro because the setters are one line each
/// and thirty-some per law; written out they would be 180 lines of the same four.
macro_rules! entry_setters {
    ($law:literal, { $($method:ident => $key:literal),* $(,)? }) => {
        $(
            #[doc = concat!("Sets `", $key, "` (docs/props.md, ", $law, ").")]
            #[must_use]
            pub fn $method(self, v: f64) -> Self {
                self.set(const { Self::LAYOUT.index_of($key) }, v)
            }
        )*
    };
}
pub(crate) use entry_setters;
