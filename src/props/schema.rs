//! One declarative description per `PROPS` layout, and what is derived from it.
//!
//! A [`Layout`] lists each entry once (index, seed name, symbol, meaning, unit, [`Class`] of
//! valid values, [`Default`](enum@Default)), the [`Rule`]s that tie entries together and the named
//! [`Fixed`] layouts that a fast path recognises (the adhesive law's Coulomb special case).
//! From that one table come:
//!
//! - the branch-light validators of the per-call fast paths, one per named fixed layout
//!   ([`Fixed`]: law 1's plain and decay-lean layouts, law 2's Coulomb special case, or
//!   [`Fixed::NONE`]): a `Plan` worked out at compile time (which one test each entry
//!   needs, which rules can still fail), read by `admits_fixed` with one copy of its body
//!   per entry (`unrolled!`), so it compiles to the straight-line code that used to be
//!   written by hand (`fric_`'s, `bench_rate`'s and `bench_adhesive`'s instruction counts are
//!   the check, docs/architecture.md);
//! - the checked parser ([`Layout::check`]), whose [`PropsError`] names the entry, its value
//!   and the requirement, with a typed [`Cause`] carrying the `PROPS` index;
//! - the defaults the laws are built with ([`Layout::resolved`]);
//! - a builder with named setters for tests, scenes and fuzz decoders ([`PropsBuilder`]);
//! - the docs/props.md table ([`Layout::markdown_table`], kept fresh by `tests/props_docs.rs`).
//!
//! Entries are numbered as in the host's Fortran, `PROPS(1)` being the law code; the arrays
//! here hold `e[i - 1] = PROPS(i)`, absent trailing entries read as 0.

use std::fmt;

use crate::LawError;

/// Which values one `PROPS` entry accepts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Class {
    /// The law code, exactly this value (`PROPS(1)`).
    Code(i32),
    /// Finite and ≥ 0.
    NonNegative,
    /// 0 (take the default) or finite and > 0: as a range 0 ≤ v < ∞, the same test as
    /// [`Class::NonNegative`].
    OffOrPositive,
    /// Finite; any value ≤ 0 means "none" (take the default).
    FiniteOrNone,
    /// Exactly 0 or 1, with what each means.
    Switch {
        /// What 0 means.
        off: &'static str,
        /// What 1 means.
        on: &'static str,
    },
    /// In [0, 1].
    UnitInterval,
    /// 0 (take the default) or in (0, 1]: as a range [0, 1].
    OffOrFraction,
    /// Finite and > 0 (no default: 0 is refused).
    Positive,
    /// Finite; 0 means "none".
    Finite,
    /// In [lo, hi], or [lo, hi) when `open_hi`.
    Interval {
        /// Lowest value.
        lo: f64,
        /// Highest value (excluded when `open_hi`).
        hi: f64,
        /// True for [lo, hi).
        open_hi: bool,
    },
    /// One of the listed integer codes, with what each means.
    Choice(&'static [(i32, &'static str)]),
}

impl Class {
    /// True when `v` is a valid value of this class (plain comparisons; the checked path, and
    /// the fast plans for the classes they have no bit test for, where the class is a constant
    /// and only its own comparisons are left once inlined).
    #[inline(always)]
    #[must_use]
    pub fn admits(self, v: f64) -> bool {
        match self {
            Class::Code(c) => v == f64::from(c),
            Class::NonNegative | Class::OffOrPositive => v.is_finite() && v >= 0.0,
            Class::FiniteOrNone => v.is_finite(),
            Class::Switch { .. } => v == 0.0 || v == 1.0,
            Class::UnitInterval | Class::OffOrFraction => (0.0..=1.0).contains(&v),
            Class::Positive => v.is_finite() && v > 0.0,
            Class::Finite => v.is_finite(),
            Class::Interval { lo, hi, open_hi } => v >= lo && (v < hi || (!open_hi && v == hi)),
            Class::Choice(options) => options.iter().any(|&(c, _)| v == f64::from(c)),
        }
    }

    /// True when `v` stands for "take the default" rather than for itself.
    #[must_use]
    pub fn is_off(self, v: f64) -> bool {
        match self {
            Class::FiniteOrNone => v <= 0.0,
            Class::OffOrPositive | Class::OffOrFraction | Class::Finite => v == 0.0,
            _ => false,
        }
    }

    /// What a message says the value must be ("must be …").
    fn requirement(self) -> String {
        match self {
            Class::Code(c) => format!("exactly {c}"),
            Class::NonNegative => "finite and ≥ 0".into(),
            Class::OffOrPositive => "finite and > 0".into(),
            Class::FiniteOrNone => "finite (≤ 0 for none)".into(),
            Class::Switch { off, on } => format!("0 ({off}) or 1 ({on})"),
            Class::UnitInterval => "in [0, 1]".into(),
            Class::OffOrFraction => "in (0, 1]".into(),
            Class::Positive => "finite and > 0".into(),
            Class::Finite => "finite".into(),
            Class::Interval { lo, hi, open_hi } => {
                format!(
                    "in [{}, {}{}",
                    number(lo),
                    number(hi),
                    if open_hi { ")" } else { "]" }
                )
            }
            Class::Choice(options) => {
                let each: Vec<String> = options.iter().map(|(c, m)| format!("{c} ({m})")).collect();
                one_of(&each)
            }
        }
    }

    /// The docs table's "valid" column: the message's words, but for a switch, whose two
    /// meanings the "meaning" column gives.
    fn valid_text(self) -> String {
        match self {
            Class::Switch { .. } => "0 or 1".into(),
            Class::Choice(options) => {
                let each: Vec<String> = options.iter().map(|(c, _)| c.to_string()).collect();
                one_of(&each)
            }
            other => other.requirement(),
        }
    }
}

/// "a", "a or b", "a, b or c".
fn one_of(each: &[String]) -> String {
    match each {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// A bound as the docs write it: −1/2 for −0.5, else the shortest decimal.
fn number(v: f64) -> String {
    if v == -0.5 {
        "−1/2".into()
    } else {
        format!("{v}")
    }
}

/// What an entry means when it is 0 or absent (or ≤ 0 for [`Class::FiniteOrNone`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Default {
    /// The entry must be given (`NPROPS` covers it).
    Required,
    /// This value.
    Value(f64),
    /// The value of another entry (`PROPS(index)`).
    Entry(usize),
    /// A function of another entry, written once in the law (`Hht::default_beta`) and named
    /// here, so that every reader and the law's constructor take the same default:
    /// `value(PROPS(of))` with `PROPS(of)` as given (itself 0 when absent).
    Derived {
        /// The entry it is a function of.
        of: usize,
        /// The law's function.
        value: LawFn,
        /// The formula, for the docs table.
        text: &'static str,
    },
    /// Worked out by the law from other inputs, as described.
    Described(&'static str),
}

/// A law's function of one entry, for [`Default::Derived`](enum@Default) (equal when it is the
/// same function).
#[derive(Clone, Copy, Debug)]
pub struct LawFn(pub fn(f64) -> f64);

impl PartialEq for LawFn {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::fn_addr_eq(self.0, other.0)
    }
}

/// One `PROPS` entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Entry {
    /// `PROPS(index)`, from 1.
    pub index: usize,
    /// The name used by the builder's setters and by messages; the seed's parameter name
    /// where the seed has one.
    pub key: &'static str,
    /// True when `key` is the seed's own name (shown in the docs table).
    pub seed_name: bool,
    /// The symbol in the field's notation ("μ_d"), or "" for none.
    pub symbol: &'static str,
    /// What it is, in a few words.
    pub meaning: &'static str,
    /// Unit (dimension), "" for a pure number.
    pub unit: &'static str,
    /// The values it accepts.
    pub class: Class,
    /// What 0 or absent means.
    pub default: Default,
    /// One more line for the docs table (which host routine reads it, what the default means),
    /// or "".
    pub note: &'static str,
}

impl Entry {
    /// `PROPS(index)`, called `key`, meaning `meaning`, valid values `class`; no symbol, no
    /// unit, 0 when absent. The other fields by the setters below, so that a layout's table
    /// reads one entry per line or chain.
    #[must_use]
    pub const fn new(index: usize, key: &'static str, meaning: &'static str, class: Class) -> Self {
        Entry {
            index,
            key,
            seed_name: false,
            symbol: "",
            meaning,
            unit: "",
            class,
            default: Default::Value(0.0),
            note: "",
        }
    }

    /// `PROPS(1)`, every layout's first entry: the law's code `code`, required.
    #[must_use]
    pub const fn law_code(code: i32) -> Self {
        Entry::new(1, "code", "law code", Class::Code(code)).when_absent(Default::Required)
    }

    /// `key` is the seed's own name.
    #[must_use]
    pub const fn seed_name(mut self) -> Self {
        self.seed_name = true;
        self
    }

    /// The symbol.
    #[must_use]
    pub const fn symbol(mut self, symbol: &'static str) -> Self {
        self.symbol = symbol;
        self
    }

    /// The unit.
    #[must_use]
    pub const fn unit(mut self, unit: &'static str) -> Self {
        self.unit = unit;
        self
    }

    /// What 0 or absent means (instead of the value 0).
    #[must_use]
    pub const fn when_absent(mut self, default: Default) -> Self {
        self.default = default;
        self
    }

    /// The docs table's extra words.
    #[must_use]
    pub const fn note(mut self, note: &'static str) -> Self {
        self.note = note;
        self
    }

    /// How messages name the entry: `key (meaning)` for a seed name, `meaning symbol`
    /// otherwise.
    fn name(&self) -> String {
        if self.seed_name {
            format!("{} ({})", self.key, self.meaning)
        } else if self.symbol.is_empty() || self.meaning.ends_with(self.symbol) {
            self.meaning.to_string()
        } else {
            format!("{} {}", self.meaning, self.symbol)
        }
    }
}

/// A rule between entries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// `PROPS(entry)`, when > 0 (given), must be ≥ `PROPS(floor)`.
    AtLeastWhenGiven {
        /// The entry the rule is about.
        entry: usize,
        /// The entry it may not be below.
        floor: usize,
        /// Why, for the message.
        why: &'static str,
    },
    /// `PROPS(entry)` must be 0 when `PROPS(on) = value` (it is not read then).
    ZeroWhen {
        /// The entry the rule is about.
        entry: usize,
        /// The entry that switches it off.
        on: usize,
        /// The value of `PROPS(on)` that does.
        value: i32,
        /// Why, for the message.
        why: &'static str,
    },
    /// `PROPS(entry)` must be > 0 when `PROPS(on) = value` (that mode needs it).
    PositiveWhen {
        /// The entry the rule is about.
        entry: usize,
        /// The entry that selects the mode.
        on: usize,
        /// The value of `PROPS(on)` that does.
        value: i32,
        /// Why, for the message.
        why: &'static str,
    },
}

impl Rule {
    /// The entry the rule is about.
    #[must_use]
    pub const fn entry(&self) -> usize {
        match *self {
            Rule::AtLeastWhenGiven { entry, .. }
            | Rule::ZeroWhen { entry, .. }
            | Rule::PositiveWhen { entry, .. } => entry,
        }
    }

    /// The other entry the rule looks at.
    #[must_use]
    pub const fn other(&self) -> usize {
        match *self {
            Rule::AtLeastWhenGiven { floor, .. } => floor,
            Rule::ZeroWhen { on, .. } | Rule::PositiveWhen { on, .. } => on,
        }
    }

    /// True when the rule holds for `v = PROPS(entry)` and `w = PROPS(other)`.
    #[inline(always)]
    #[must_use]
    pub fn holds(&self, v: f64, w: f64) -> bool {
        match *self {
            Rule::AtLeastWhenGiven { .. } => v <= 0.0 || v >= w,
            Rule::ZeroWhen { value, .. } => w != f64::from(value) || v == 0.0,
            Rule::PositiveWhen { value, .. } => w != f64::from(value) || v > 0.0,
        }
    }
}

/// Other meanings of some entries, taken when `PROPS(on) = value` (law 1's steady transport
/// reads `PROPS(14..16)` as ω, the axis and the γ̇_crit variant instead of HHT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    /// Its name in the docs.
    pub name: &'static str,
    /// The entry that selects it.
    pub on: usize,
    /// The value of `PROPS(on)` that does.
    pub value: i32,
    /// The entries it gives another meaning, by their index.
    pub entries: &'static [Entry],
}

/// What a named fixed layout requires of one entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fix {
    /// ±0.
    Zero,
    /// "None" (≤ 0, finite) or equal to `PROPS(index)`.
    NoneOrEqual(usize),
    /// 0 or equal to `PROPS(index)` (law 1's isotropy: μ₂ absent or μ₂ = μ).
    ZeroOrEqual(usize),
    /// Exactly this value (the mode a fast path is written for).
    Is(i32),
    /// One of these values, tested by the fast reader's own `match` that maps them to the
    /// law's type (the stick mode), so it is tested once: the validator leaves it alone, and
    /// only uses the list to know which rules and variants cannot apply.
    MappedBy(&'static [i32]),
}

/// A named fixed layout: entries pinned to one meaning, the others as the layout allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fixed {
    /// Its name in the docs.
    pub name: &'static str,
    /// The pinned entries.
    pub fixed: &'static [(usize, Fix)],
}

/// A `PROPS` layout: one law's entries, rules and fixed layouts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// The law's name in messages ("adhesive law").
    pub law: &'static str,
    /// `PROPS(1)`.
    pub code: i32,
    /// Entries `PROPS(1..=entries.len())`, in order.
    pub entries: &'static [Entry],
    /// The rules between entries.
    pub rules: &'static [Rule],
    /// Other meanings of some entries, selected by another entry's value.
    pub variants: &'static [Variant],
}

/// What is wrong with a `PROPS` array, with the index of the entry where there is one.
#[derive(Clone, Debug, PartialEq)]
pub enum Cause {
    /// Fewer entries than the required ones.
    TooFew {
        /// `NPROPS`.
        given: usize,
    },
    /// A non-zero entry past the layout.
    Unused {
        /// `PROPS(index)`.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// An entry outside its [`Class`].
    OutOfClass {
        /// `PROPS(index)`.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A [`Rule`] broken.
    Broken {
        /// The entry the rule is about.
        index: usize,
        /// The rule.
        rule: Rule,
        /// Its value.
        value: f64,
        /// The value of the other entry.
        other: f64,
    },
    /// Valid entries that a law's own condition refuses, beyond what the layout can say
    /// (said by the law's builder from validated entries).
    Refused {
        /// The `PROPS` index the refusal is said of.
        index: usize,
        /// The law's text (law 1's `Refusal`, src/props/coulomb.rs).
        message: String,
    },
    /// A law refused a value that the layout admits (its message, said of `PROPS(index)`).
    Law {
        /// `PROPS(index)`.
        index: usize,
        /// The law's refusal.
        error: LawError,
    },
}

/// A refused `PROPS` array: the layout and the cause. Becomes a [`LawError::Parameter`] with
/// the same text at the routines' boundary.
#[derive(Clone, Debug, PartialEq)]
pub struct PropsError {
    layout: &'static Layout,
    cause: Cause,
    /// The description of the offending entry in force (a [`Variant`]'s, or the layout's).
    entry: Option<&'static Entry>,
}

impl PropsError {
    /// A law's refusal of `PROPS(index)`.
    #[must_use]
    pub fn law(layout: &'static Layout, index: usize, error: LawError) -> Self {
        PropsError {
            layout,
            cause: Cause::Law { index, error },
            entry: None,
        }
    }

    /// A builder's refusal of valid entries (`layout`'s).
    #[cold]
    #[inline(never)]
    #[must_use]
    pub fn refused(layout: &'static Layout, index: usize, message: String) -> Self {
        PropsError {
            layout,
            cause: Cause::Refused { index, message },
            entry: None,
        }
    }

    /// `PROPS(index)` of the entries `e` outside its class: for a reader that tests a pinned
    /// entry by its own match (`Fix::MappedBy`) and so meets the value the class refuses.
    #[cold]
    #[inline(never)]
    #[must_use]
    pub fn out_of_class(layout: &'static Layout, e: &[f64], index: usize) -> Self {
        PropsError {
            layout,
            cause: Cause::OutOfClass {
                index,
                value: e[index - 1],
            },
            entry: Some(layout.entry_in(e, index)),
        }
    }

    /// The cause.
    #[must_use]
    pub fn cause(&self) -> &Cause {
        &self.cause
    }

    /// The `PROPS` index of the offending entry, when there is one (not for too few entries).
    #[must_use]
    pub fn index(&self) -> Option<usize> {
        match self.cause {
            Cause::TooFew { .. } => None,
            Cause::Refused { index, .. } => Some(index),
            Cause::Unused { index, .. }
            | Cause::OutOfClass { index, .. }
            | Cause::Broken { index, .. }
            | Cause::Law { index, .. } => Some(index),
        }
    }
}

impl fmt::Display for PropsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let layout = self.layout;
        match &self.cause {
            Cause::TooFew { given } => {
                let required: Vec<String> = layout
                    .required()
                    .map(|e| match e.class {
                        Class::Code(c) => format!("PROPS({}) = {c}", e.index),
                        _ if e.seed_name || e.symbol.is_empty() => {
                            format!("PROPS({}) = {}", e.index, e.key)
                        }
                        _ => format!("PROPS({}) = {}", e.index, e.symbol),
                    })
                    .collect();
                write!(
                    f,
                    "NPROPS = {given} but the {} needs at least {} ({})",
                    layout.law,
                    required.len(),
                    required.join(", ")
                )
            }
            Cause::Unused { index, value } => write!(
                f,
                "PROPS({index}) = {value} is not used by the {} (PROPS(1..{})); refusing to \
                 ignore it",
                layout.law,
                layout.entries.len()
            ),
            Cause::Refused { message, .. } => f.write_str(message),
            Cause::OutOfClass { index, value } => {
                let e = self.entry.unwrap_or_else(|| layout.entry(*index));
                if let Class::Switch { .. } = e.class {
                    // A switch selects one of two things: "PROPS(16) = 2 must select the …".
                    return write!(
                        f,
                        "PROPS({index}) = {value} must select the {}: {}",
                        e.meaning,
                        e.class.requirement()
                    );
                }
                write!(f, "PROPS({index}): {} = {value} must be ", e.name())?;
                write!(f, "{}", e.class.requirement())?;
                match (e.class, e.default) {
                    (Class::OffOrFraction | Class::OffOrPositive, Default::Value(d)) => {
                        write!(f, " (0 → {d})")
                    }
                    _ => Ok(()),
                }
            }
            Cause::Broken {
                index,
                rule: Rule::AtLeastWhenGiven { floor, why, .. },
                value,
                other,
            } => write!(
                f,
                "PROPS({index}): {} = {value} is below {} = {other}: {why}",
                layout.entry(*index).key,
                layout.entry(*floor).key
            ),
            Cause::Broken {
                index,
                rule: Rule::ZeroWhen {
                    on, value: w, why, ..
                },
                value,
                ..
            } => write!(
                f,
                "PROPS({index}) = {value} is not read when PROPS({on}) = {w} ({why}); refusing \
                 to ignore it"
            ),
            Cause::Broken {
                index,
                rule:
                    Rule::PositiveWhen {
                        on, value: w, why, ..
                    },
                value,
                ..
            } => write!(
                f,
                "PROPS({index}): {} = {value} must be > 0 when PROPS({on}) = {w} ({why})",
                self.entry.unwrap_or_else(|| layout.entry(*index)).name()
            ),
            Cause::Law {
                index,
                error: LawError::Parameter(m),
            } => write!(f, "PROPS({index}): {m}"),
            Cause::Law { error, .. } => write!(f, "{error}"),
        }
    }
}

impl From<PropsError> for LawError {
    fn from(e: PropsError) -> Self {
        match e.cause {
            // Not a parameter's fault (a configuration or numerical error): passed on as is.
            Cause::Law {
                error: error @ (LawError::Config(_) | LawError::Input(_) | LawError::Numerical(_)),
                ..
            } => error,
            _ => LawError::Parameter(e.to_string()),
        }
    }
}

/// `body` once per listed index, with `$i` a constant (a loop the compiler is sure to unroll).
macro_rules! unrolled {
    ($i:ident in [$($n:literal)*] $body:block) => {
        $({
            const $i: usize = $n;
            $body
        })*
    };
}

/// Top bit clear exactly when 0 ≤ v < ∞ (see `props::range_flag`).
#[inline(always)]
fn range_flag(v: f64) -> u64 {
    super::range_flag(v)
}

mod plan;
pub(crate) use plan::{FastLayout, Plan, admits_fixed};

impl Layout {
    /// `PROPS(index)`'s description. Panics on an index outside the layout (a programming
    /// error in a schema, caught by the schema's tests).
    #[must_use]
    pub const fn entry(&self, index: usize) -> &Entry {
        &self.entries[index - 1]
    }

    /// `PROPS(index)`'s description in force for the entries `e` (`e[i - 1] = PROPS(i)`): a
    /// [`Variant`]'s when `e` selects one that redefines it, else the layout's.
    #[must_use]
    pub fn entry_in(&'static self, e: &[f64], index: usize) -> &'static Entry {
        for variant in self.variants {
            if e.get(variant.on - 1) != Some(&f64::from(variant.value)) {
                continue;
            }
            if let Some(entry) = variant.entries.iter().find(|x| x.index == index) {
                return entry;
            }
        }
        &self.entries[index - 1]
    }

    /// The index of the entry called `key` (also a variant's entry); a compile-time error when used in a `const` with
    /// a key the layout does not have.
    #[must_use]
    pub const fn index_of(&self, key: &str) -> usize {
        let mut i = 0;
        while i < self.entries.len() {
            if const_str_eq(self.entries[i].key, key) {
                return self.entries[i].index;
            }
            i += 1;
        }
        let mut v = 0;
        while v < self.variants.len() {
            let entries = self.variants[v].entries;
            let mut i = 0;
            while i < entries.len() {
                if const_str_eq(entries[i].key, key) {
                    return entries[i].index;
                }
                i += 1;
            }
            v += 1;
        }
        panic!("no PROPS entry of that name in the layout");
    }

    /// The entries that must be given: the law code and those without a default.
    pub fn required(&self) -> impl Iterator<Item = &Entry> {
        self.entries[..self.required_len()].iter()
    }

    /// The smallest `NPROPS`: the index of the last entry without a default (the law code
    /// at least). A schema test checks that no entry after it is required.
    #[must_use]
    pub const fn required_len(&self) -> usize {
        let mut n = 1;
        let mut i = 0;
        while i < self.entries.len() {
            if matches!(self.entries[i].default, Default::Required) {
                n = self.entries[i].index;
            }
            i += 1;
        }
        n
    }

    /// The checked parser: the entries padded with zeros to the layout's length, or the first
    /// thing wrong, in entry order (each entry's class, then the rules about it).
    pub fn check<const N: usize>(&'static self, props: &[f64]) -> Result<[f64; N], PropsError> {
        debug_assert_eq!(N, self.entries.len());
        let refuse = |cause, entry| {
            Err(PropsError {
                layout: self,
                cause,
                entry,
            })
        };
        if props.len() < self.required_len() {
            return refuse(Cause::TooFew { given: props.len() }, None);
        }
        if let Some((i, &value)) = props.iter().enumerate().skip(N).find(|(_, v)| **v != 0.0) {
            return refuse(
                Cause::Unused {
                    index: i + 1,
                    value,
                },
                None,
            );
        }
        let e: [f64; N] = std::array::from_fn(|i| props.get(i).copied().unwrap_or(0.0));
        for (index, &value) in (1..).zip(&e) {
            let entry = self.entry_in(&e, index);
            if !entry.class.admits(value) {
                return refuse(Cause::OutOfClass { index, value }, Some(entry));
            }
            for &rule in self.rules {
                let (v, w) = (e[rule.entry() - 1], e[rule.other() - 1]);
                if rule.entry() == index && !rule.holds(v, w) {
                    return refuse(
                        Cause::Broken {
                            index,
                            rule,
                            value: v,
                            other: w,
                        },
                        Some(entry),
                    );
                }
            }
        }
        Ok(e)
    }

    /// `PROPS(index)` of valid entries `e` with its default applied: the value the law is
    /// built with.
    #[inline(always)]
    #[must_use]
    pub fn resolved<const N: usize>(&self, e: &[f64; N], index: usize) -> f64 {
        self.resolved_in(e, index)
    }

    /// [`Layout::resolved`] for entries given as a slice (`e[i - 1] = PROPS(i)`, entries past
    /// its end absent).
    #[inline(always)]
    #[must_use]
    pub fn resolved_in(&self, e: &[f64], index: usize) -> f64 {
        let entry = self.entry(index);
        // Past the end: absent, i.e. 0.
        let get = |i: usize| if i <= e.len() { e[i - 1] } else { 0.0 };
        let v = get(index);
        match entry.default {
            Default::Value(d) if entry.class.is_off(v) => d,
            Default::Entry(j) if entry.class.is_off(v) => get(j),
            Default::Derived { of, value, .. } if entry.class.is_off(v) => (value.0)(get(of)),
            _ => v,
        }
    }

    /// The rows of the docs/props.md table, in order: per entry, each variant's meaning of it
    /// first, then the layout's own, each saying when it holds. The one listing of the layout's
    /// entries for readers outside the crate: the markdown table ([`Layout::markdown_table`])
    /// and the C API (`ifl_props_entry`) are both written from it.
    #[must_use]
    pub fn table_rows(&self) -> Vec<TableRow> {
        let mut out = Vec::new();
        for base in self.entries {
            for variant in self.variants {
                if let Some(e) = variant.entries.iter().find(|x| x.index == base.index) {
                    out.push(self.table_row(e, vec![(variant.on, variant.value, true)]));
                }
            }
            let otherwise = self
                .variants
                .iter()
                .filter(|v| v.entries.iter().any(|x| x.index == base.index))
                .map(|v| (v.on, v.value, false))
                .collect();
            out.push(self.table_row(base, otherwise));
        }
        out
    }

    /// The docs/props.md table of this layout (GitHub markdown), from [`Layout::table_rows`].
    #[must_use]
    pub fn markdown_table(&self) -> String {
        let mut out = String::from(
            "| entry | seed name | symbol | meaning | units | default (0 or absent) | valid |\n\
             |---|---|---|---|---|---|---|\n",
        );
        for row in self.table_rows() {
            out += &row.markdown();
        }
        out
    }
}

/// One row of a layout's table ([`Layout::table_rows`]): an entry, in one meaning, with the
/// table's texts.
#[derive(Clone, Debug, PartialEq)]
pub struct TableRow {
    /// The entry in this meaning (a variant's entry, or the layout's own).
    pub entry: Entry,
    /// When this meaning holds: `(on, value, equal)` for `PROPS(on) = value` (`equal`) or
    /// `PROPS(on) ≠ value`, all of them; empty for always.
    pub when: Vec<(usize, i32, bool)>,
    /// What 0 or absent means, as the table says it.
    pub default: String,
    /// The value 0 or absent stands for, when it is one number (`Default::Value`); `None` when
    /// the entry is required or its default is another entry or a function of one.
    pub default_value: Option<f64>,
    /// The meaning, with what each value of a switch or choice means and the entry's note.
    pub meaning: String,
    /// The values it accepts, with the rules about it.
    pub valid: String,
}

impl TableRow {
    /// The condition in plain text: "PROPS(7) = 3", "PROPS(7) ≠ 3" (joined by ", "), or "".
    #[must_use]
    pub fn when_text(&self) -> String {
        let each: Vec<String> = self
            .when
            .iter()
            .map(|&(on, value, equal)| {
                format!("PROPS({on}) {} {value}", if equal { "=" } else { "≠" })
            })
            .collect();
        each.join(", ")
    }

    /// The row in the docs table's markdown.
    fn markdown(&self) -> String {
        let dash = |s: &str| {
            if s.is_empty() {
                "—".to_string()
            } else {
                s.to_string()
            }
        };
        let when: String = self
            .when
            .iter()
            .map(|&(on, value, equal)| {
                if equal {
                    format!(" (`PROPS({on}) = {value}`)")
                } else {
                    format!(" (`PROPS({on})` ≠ {value})")
                }
            })
            .collect();
        let e = &self.entry;
        format!(
            "| `PROPS({})`{when} | {} | {} | {} | {} | {} | {} |\n",
            e.index,
            if e.seed_name {
                format!("`{}`", e.key)
            } else {
                "—".into()
            },
            dash(e.symbol),
            self.meaning,
            dash(e.unit),
            self.default,
            self.valid
        )
    }
}

#[cfg(test)]
impl Layout {
    /// Unit tests: the table is well formed. Entries are numbered in order, a required entry
    /// never follows an optional one, every optional entry admits 0 and −0 (the fast paths read
    /// an absent entry as 0 and test only the given ones), every rule names entries of the
    /// layout, and a variant's switch is a value its entry accepts and it redefines entries of
    /// the layout.
    pub(crate) fn assert_well_formed(&self) {
        let mut optional_seen = false;
        for (i, e) in self.entries.iter().enumerate() {
            assert_eq!(e.index, i + 1, "{e:?}");
            let required = matches!(e.default, Default::Required);
            assert!(!(required && optional_seen), "{e:?}");
            optional_seen |= !required;
            if !required {
                assert!(e.class.admits(0.0) && e.class.admits(-0.0), "{e:?}");
            }
        }
        let len = self.entries.len();
        for rule in self.rules {
            assert!(rule.entry() <= len && rule.other() <= len, "{rule:?}");
        }
        for variant in self.variants {
            let switch = self.entry(variant.on).class;
            assert!(switch.admits(f64::from(variant.value)), "{variant:?}");
            for e in variant.entries {
                assert!(e.index <= len, "{e:?}");
            }
        }
    }
}

impl Layout {
    /// One row of [`Layout::table_rows`]: entry `e`, holding `when`.
    fn table_row(&self, e: &Entry, when: Vec<(usize, i32, bool)>) -> TableRow {
        let default = match e.default {
            Default::Required if matches!(e.class, Class::Code(_)) => "—".to_string(),
            Default::Required => "— (required)".to_string(),
            Default::Value(d) => format!("{d}"),
            Default::Entry(j) => {
                // "None" is any value ≤ 0 for FiniteOrNone, only 0 otherwise.
                let none = if matches!(e.class, Class::FiniteOrNone) {
                    "none: "
                } else {
                    ""
                };
                format!("{none}{} = {}", e.symbol, self.entry(j).symbol)
            }
            Default::Derived { text, .. } | Default::Described(text) => text.to_string(),
        };
        let mut valid = e.class.valid_text();
        for rule in self.rules.iter().filter(|r| r.entry() == e.index) {
            valid += &match *rule {
                Rule::AtLeastWhenGiven { floor, .. } => {
                    format!("; when > 0, ≥ `{}`", self.entry(floor).key)
                }
                Rule::ZeroWhen { on, value, .. } => format!("; 0 when `PROPS({on}) = {value}`"),
                Rule::PositiveWhen { on, value, .. } => {
                    format!("; > 0 when `PROPS({on}) = {value}`")
                }
            };
        }
        let mut meaning = e.meaning.to_string();
        match e.class {
            Class::Switch { off, on } => meaning += &format!(": 0 {off}, 1 {on}"),
            Class::Choice(options) => {
                let each: Vec<String> = options.iter().map(|(c, m)| format!("{c} {m}")).collect();
                meaning += &format!(": {}", each.join(", "));
            }
            _ => {}
        }
        if !e.note.is_empty() {
            meaning += &format!(" ({})", e.note);
        }
        TableRow {
            entry: *e,
            when,
            default,
            default_value: match e.default {
                Default::Value(d) => Some(d),
                _ => None,
            },
            meaning,
            valid,
        }
    }
}

impl Fixed {
    /// No entry pinned: the whole layout as it comes (a fast path that only decides valid or
    /// not).
    pub const NONE: Fixed = Fixed {
        name: "as given",
        fixed: &[],
    };

    /// The pins `a` then `b`, `N` of them: a fixed layout's list from shared parts (a `const`
    /// can then hold it).
    #[must_use]
    pub const fn joined<const N: usize>(
        a: &[(usize, Fix)],
        b: &[(usize, Fix)],
    ) -> [(usize, Fix); N] {
        assert!(a.len() + b.len() == N);
        let mut out = [(0, Fix::Zero); N];
        let mut k = 0;
        while k < N {
            out[k] = if k < a.len() { a[k] } else { b[k - a.len()] };
            k += 1;
        }
        out
    }

    /// What this fixed layout pins `PROPS(index)` to, if anything.
    #[inline(always)]
    #[must_use]
    pub const fn pin(&self, index: usize) -> Option<Fix> {
        let mut k = 0;
        while k < self.fixed.len() {
            if self.fixed[k].0 == index {
                return Some(self.fixed[k].1);
            }
            k += 1;
        }
        None
    }
}

const fn const_str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// A `PROPS` array built entry by entry, by name: for tests, scenes, fuzz decoders and
/// harness generators, so that none of them builds `PROPS` by position. Laws wrap it in
/// builders with one named setter per entry (`props::LawBuilder`, `AdhesiveBuilder`).
#[derive(Clone, Debug, PartialEq)]
pub struct PropsBuilder {
    layout: &'static Layout,
    entries: Vec<f64>,
}

impl PropsBuilder {
    /// Every entry at its "0 / absent" value, `PROPS(1)` the law code.
    #[must_use]
    pub fn new(layout: &'static Layout) -> Self {
        let mut entries = vec![0.0; layout.entries.len()];
        entries[0] = f64::from(layout.code);
        PropsBuilder { layout, entries }
    }

    /// Sets `PROPS(index)`.
    ///
    /// # Panics
    /// When `index` is not in `1..=` the layout's length (the laws' named setters pass
    /// constant, checked indices).
    #[must_use]
    pub fn set(mut self, index: usize, v: f64) -> Self {
        self.entries[index - 1] = v;
        self
    }

    /// The whole layout, `NPROPS` = its length.
    #[must_use]
    pub fn build(&self) -> Vec<f64> {
        self.entries.clone()
    }

    /// The first `nprops` entries (a host that leaves out trailing ones; `nprops` larger than
    /// the layout pads with zeros).
    #[must_use]
    pub fn build_first(&self, nprops: usize) -> Vec<f64> {
        let mut v = self.entries.clone();
        v.resize(nprops, 0.0);
        v
    }

    /// The layout.
    #[must_use]
    pub fn layout(&self) -> &'static Layout {
        self.layout
    }
}
