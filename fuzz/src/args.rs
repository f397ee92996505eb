//! The arguments of one host call, by their Fortran names, and the one decoder every case draws
//! them with: a table per entry point of (names, how they are drawn), read in order.
//!
//! Every argument is an array, as the host passes it (by reference): a scalar is an array of one
//! entry, and an array has exactly the length the call declares, computed from the counts drawn
//! before it (`TAU(NFDIR)`: `Reals(of("NFDIR"))`), so AddressSanitizer reports any access past
//! it. The case files keep only what differs between entry points: the tables, the entries a
//! table cannot say (`PROPS`, status codes, names), the call and the property checks.

use std::ffi::c_int;
use std::fmt;
use std::ops::{Index, IndexMut};

use super::bytes::{Bytes, len};
use super::contract::{Names, UNWRITTEN, last_error, unwritten};
use interfacial::abi::ifl_clear_error;

/// How many entries an array has, from the counts already drawn.
#[derive(Clone, Copy, Debug)]
pub enum Len {
    /// A fixed number: 1 for a scalar, 2 for `TIME(2)`.
    Fixed(usize),
    /// `k` times the count named (`PREDEF(2,NPRED)`: `Times(2, "NPRED")`), a negative count
    /// being 0.
    Times(usize, &'static str),
    /// The count named, squared (`ALOCALDIR(MCRD,MCRD)`).
    Square(&'static str),
    /// The product of the two counts named (`fieldAvg(nBlock,nFields)`).
    Product(&'static str, &'static str),
}

/// A scalar.
pub const ONE: Len = Len::Fixed(1);

/// As many entries as the count named: `STRESS(NDIR)` is `of("NDIR")`.
pub const fn of(count: &'static str) -> Len {
    Len::Times(1, count)
}

/// How the arguments of one table row are drawn from the bytes.
#[derive(Clone, Copy, Debug)]
pub enum Draw {
    /// An integer from the list, by one byte ([`Bytes::pick`]).
    Pick(&'static [c_int]),
    /// An integer in 0..=65535, by two bytes: element and node numbers.
    Number,
    /// An integer the fuzzer does not vary (no bytes).
    Int(c_int),
    /// Reals of any class ([`Bytes::real`]).
    Reals(Len),
    /// `PNEWDT` on entry, ≥ 1 mostly ([`Bytes::large`]).
    Large,
}

/// One row of a decoding table: these arguments, each drawn so, in this order.
pub type Row = (&'static [&'static str], Draw);

/// Arrays by name, in the order first set.
#[derive(Clone, PartialEq)]
struct Table<T>(Vec<(&'static str, Vec<T>)>);

impl<T> Default for Table<T> {
    fn default() -> Self {
        Table(Vec::new())
    }
}

impl<T> Table<T> {
    /// Where `name` is. Names are `&'static str` literals, and the same literal is mostly the
    /// same object: it is looked for by address first, and only then by its bytes, so a lookup
    /// seldom compares strings (each string comparison is also a hook in the fuzzer).
    fn slot(&self, name: &str) -> Option<usize> {
        let names = || self.0.iter().map(|(n, _)| *n);
        (names().position(|n| std::ptr::eq(n, name))).or_else(|| names().position(|n| n == name))
    }

    fn get(&self, name: &str, kind: &str) -> &Vec<T> {
        match self.slot(name) {
            Some(i) => &self.0[i].1,
            None => panic!("no {kind} argument {name}"),
        }
    }

    fn get_mut(&mut self, name: &str, kind: &str) -> &mut Vec<T> {
        match self.slot(name) {
            Some(i) => &mut self.0[i].1,
            None => panic!("no {kind} argument {name}"),
        }
    }

    fn put(&mut self, name: &'static str, values: Vec<T>) {
        match self.slot(name) {
            Some(i) => self.0[i].1 = values,
            None => self.0.push((name, values)),
        }
    }

    /// Adds `name`, which a table draws or a call writes once (checked in the tests' debug
    /// builds): no search, so a decoder does not compare every new name with all before it.
    fn add(&mut self, name: &'static str, values: Vec<T>) {
        debug_assert!(self.slot(name).is_none(), "argument {name} twice");
        self.0.push((name, values));
    }
}

/// The arguments of one call by name: integers and reals, each an array.
#[derive(Clone, Default)]
pub struct Args {
    ints: Table<c_int>,
    reals: Table<f64>,
}

impl Args {
    /// No arguments yet.
    pub fn new() -> Self {
        Args::default()
    }

    /// Draws the arguments of `table`, row by row and name by name, after those already drawn
    /// (which the lengths may name).
    pub fn draw(&mut self, b: &mut Bytes, table: &[Row]) {
        for &(names, how) in table {
            for &name in names {
                match how {
                    Draw::Pick(list) => self.ints.add(name, vec![b.pick(list)]),
                    Draw::Number => self.ints.add(name, vec![c_int::from(b.u16())]),
                    Draw::Int(v) => self.ints.add(name, vec![v]),
                    Draw::Reals(n) => {
                        let n = self.count(n);
                        self.reals.add(name, b.reals(n));
                    }
                    Draw::Large => self.reals.add(name, vec![b.large()]),
                }
            }
        }
    }

    /// The number of entries `n` says, from the counts drawn so far.
    pub fn count(&self, n: Len) -> usize {
        match n {
            Len::Fixed(k) => k,
            Len::Times(k, count) => k * self.len_of(count),
            Len::Square(count) => self.len_of(count) * self.len_of(count),
            Len::Product(a, b) => self.len_of(a) * self.len_of(b),
        }
    }

    /// The count named as a length (a negative one is 0).
    pub fn len_of(&self, count: &str) -> usize {
        len(self.int(count))
    }

    /// Sets (or adds) the real array `name`.
    pub fn put(&mut self, name: &'static str, values: Vec<f64>) {
        self.reals.put(name, values);
    }

    /// Sets (or adds) the integer array `name`.
    pub fn put_ints(&mut self, name: &'static str, values: Vec<c_int>) {
        self.ints.put(name, values);
    }

    /// Sets (or adds) the integer scalar `name`.
    pub fn set_int(&mut self, name: &'static str, value: c_int) {
        self.put_ints(name, vec![value]);
    }

    /// The integer array `name`; panics naming it when there is none (a typo in a case).
    pub fn ints(&self, name: &str) -> &Vec<c_int> {
        self.ints.get(name, "integer")
    }

    /// The integer array `name`, to change it.
    pub fn ints_mut(&mut self, name: &str) -> &mut Vec<c_int> {
        self.ints.get_mut(name, "integer")
    }

    /// The integer scalar `name`.
    pub fn int(&self, name: &str) -> c_int {
        self.ints(name)[0]
    }

    /// The real scalar `name`.
    pub fn real(&self, name: &str) -> f64 {
        self[name][0]
    }

    /// Whether a real argument `name` exists.
    pub fn has(&self, name: &str) -> bool {
        self.reals.slot(name).is_some()
    }

    /// The real argument `name` as the host passes an input.
    pub fn ptr(&self, name: &str) -> *const f64 {
        self[name].as_ptr()
    }

    /// The real argument `name` as the host passes an output.
    pub fn ptr_mut(&mut self, name: &str) -> *mut f64 {
        self[name].as_mut_ptr()
    }

    /// The integer argument `name` as the host passes an input.
    pub fn int_ptr(&self, name: &str) -> *const c_int {
        self.ints(name).as_ptr()
    }

    /// The integer argument `name` as the host passes an output.
    pub fn int_ptr_mut(&mut self, name: &str) -> *mut c_int {
        self.ints_mut(name).as_mut_ptr()
    }

    /// What a call may write: the in-out arguments `kept` as they are on entry, and the
    /// outputs `fresh`, each of its declared length, filled with [`UNWRITTEN`].
    pub fn outputs(&self, kept: &[&'static str], fresh: &[(&'static str, Len)]) -> Args {
        let mut out = Args::new();
        for &name in kept {
            if self.has(name) {
                out.reals.add(name, self[name].clone());
            } else {
                out.ints.add(name, self.ints(name).clone());
            }
        }
        for &(name, n) in fresh {
            out.reals.add(name, vec![UNWRITTEN; self.count(n)]);
        }
        out
    }

    /// The entries of the real arrays `names` that a call wrote (not [`UNWRITTEN`]).
    pub fn written(&self, names: &[&str]) -> Vec<f64> {
        let all = names.iter().flat_map(|n| self[*n].iter());
        all.copied().filter(|x| !unwritten(x)).collect()
    }

    /// Whether every argument is bit for bit that of `other` (NaN payloads and signed zeros
    /// included), the two holding the same names in the same order (a clone, or two values
    /// built alike): an input left alone, a call that wrote what was expected.
    pub fn same(&self, other: &Args) -> bool {
        let same_bits = |a: &[f64], b: &[f64]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
        };
        self.ints == other.ints
            && self.reals.0.len() == other.reals.0.len()
            && (self.reals.0.iter().zip(&other.reals.0))
                .all(|((n, a), (m, b))| n == m && same_bits(a, b))
    }
}

/// `p`, or NULL when `null`: an argument that a broken host passes as NULL.
pub fn or_null<T>(p: *const T, null: bool) -> *const T {
    if null { std::ptr::null() } else { p }
}

/// [`or_null`] for an output.
pub fn or_null_mut<T>(p: *mut T, null: bool) -> *mut T {
    if null { std::ptr::null_mut() } else { p }
}

/// One call as every case makes it: `call` gets copies of `args` and `names` to pass as inputs
/// and the arguments to pass as outputs (`args.outputs(kept, fresh)`); afterwards every input
/// must be bit for bit what it was (never written), and what the call wrote comes back with
/// its message. `Err` when an input was written.
pub fn call(
    args: &Args,
    names: &Names,
    kept: &[&'static str],
    fresh: &[(&'static str, Len)],
    call: impl FnOnce(&Args, &Names, &mut Args),
) -> Result<Outputs, String> {
    let (inputs, input_names) = (args.clone(), names.clone());
    let mut out = args.outputs(kept, fresh);
    ifl_clear_error();
    call(&inputs, &input_names, &mut out);
    let message = last_error();
    if !inputs.same(args) || input_names != *names {
        return Err("an input argument was written".into());
    }
    Ok(Outputs { args: out, message })
}

impl Index<&str> for Args {
    type Output = Vec<f64>;

    /// The real array `name`; panics naming it when there is none (a typo in a case).
    fn index(&self, name: &str) -> &Vec<f64> {
        self.reals.get(name, "real")
    }
}

impl IndexMut<&str> for Args {
    fn index_mut(&mut self, name: &str) -> &mut Vec<f64> {
        self.reals.get_mut(name, "real")
    }
}

/// `{NFDIR: [2], …, TAU: [0.5, -0.0], …}`: integers, then reals, each in the order drawn.
impl fmt::Debug for Args {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ints = self.ints.0.iter().map(|(n, v)| (n, v as &dyn fmt::Debug));
        let reals = self.reals.0.iter().map(|(n, v)| (n, v as &dyn fmt::Debug));
        f.debug_map().entries(ints.chain(reals)).finish()
    }
}

/// What a call wrote (see [`Args::outputs`]) and the library's message after it (empty on
/// success).
#[derive(Clone, Debug)]
pub struct Outputs {
    pub args: Args,
    pub message: String,
}

impl Outputs {
    /// The integer scalar `name` after the call.
    pub fn int(&self, name: &str) -> c_int {
        self.args.int(name)
    }

    /// The real scalar `name` after the call.
    pub fn real(&self, name: &str) -> f64 {
        self.args.real(name)
    }
}

impl Index<&str> for Outputs {
    type Output = Vec<f64>;

    fn index(&self, name: &str) -> &Vec<f64> {
        &self.args[name]
    }
}
