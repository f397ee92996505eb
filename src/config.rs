//! The configuration file: a TOML file named by `INTERFACIAL_CONFIG`, keyed by interaction name,
//! giving the laws of the routines that have no `PROPS` (GAPCON). Read and validated once, at
//! first use, by whichever thread comes first; every error names the file, the line and the key.
//!
//! ```toml
//! [interactions.SI1.conductance]
//! law = "constant"
//! k = 2.0
//!
//! [interactions."*".conductance]          # fallback for every other interaction
//! law = "pressure-table"
//! table = [[0.0, 1.0], [100.0, 3.0]]      # [p, k] rows; [p, k, θ̄] for temperature dependence
//! ```
//!
//! It also holds the μ tables of `fric_`/`fric_coef_` (`PROPS(8) = 2`), looked up the same way:
//!
//! ```toml
//! [interactions.SI1.friction]
//! table = [[0.5, 0.0], [0.3, 2.0]]        # [μ, γ̇] rows; [μ, γ̇, p] or [μ, γ̇, p, θ̄] too
//! ```
//!
//! The full schema is in `docs/config.md`.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use serde::Deserialize;
use toml::Spanned;

use crate::LawError;
use crate::laws::friction_table::FrictionTable;
use crate::laws::frictional_heat::{FrictionalHeat, HeatShare, SlidingSpeed};
use crate::laws::gap_conductance::{Conduction, GapLaw};
use crate::laws::gap_radiation::Radiation;
use crate::laws::table::{Table1, TemperatureTable};

/// Environment variable naming the configuration file.
pub const CONFIG_ENV: &str = "INTERFACIAL_CONFIG";

/// Name of the fallback entry.
pub const FALLBACK: &str = "*";

/// Default c of the Cooper–Mikic–Yovanovich correlation.
pub const CMY_DEFAULT_C: f64 = 1.25;

// The file's tables as serde reads them, each refusing a key it does not know
// (`deny_unknown_fields` on every one): a misspelt key is an error that names it, never a
// setting silently left at its default.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileSpec {
    #[serde(default)]
    interactions: BTreeMap<String, Spanned<InteractionSpec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InteractionSpec {
    conductance: Option<Spanned<ConductanceSpec>>,
    radiation: Option<Spanned<RadiationSpec>>,
    friction: Option<Spanned<FrictionSpec>>,
    heat: Option<Spanned<HeatSpec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct HeatSpec {
    fraction: Option<Spanned<f64>>,
    slave_share: Option<Spanned<f64>>,
    slave_effusivity: Option<Spanned<f64>>,
    master_effusivity: Option<Spanned<f64>>,
    speed: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrictionSpec {
    table: Spanned<Vec<Spanned<Vec<f64>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ConductanceSpec {
    law: Spanned<String>,
    k: Option<Spanned<f64>>,
    table: Option<Spanned<Vec<Vec<f64>>>>,
    k_gas: Option<Spanned<f64>>,
    g0: Option<Spanned<f64>>,
    min_gap: Option<Spanned<f64>>,
    c: Option<Spanned<f64>>,
    k_s: Option<Spanned<f64>>,
    m: Option<Spanned<f64>>,
    sigma: Option<Spanned<f64>>,
    #[serde(rename = "H_c")]
    h_c: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RadiationSpec {
    view_factor: Option<Spanned<f64>>,
    stefan_boltzmann: Option<Spanned<f64>>,
    absolute_zero: Option<Spanned<f64>>,
}

/// A validated configuration file.
#[derive(Clone, Debug)]
pub struct Config {
    path: String,
    /// (name as written, law); names are unique ignoring ASCII case.
    gap_laws: Vec<(String, GapLaw)>,
    /// [`name_key`] of each entry of `gap_laws`, same order: the per-call lookup scans these
    /// eight-byte keys and compares names only on a key match.
    gap_keys: Vec<u64>,
    fallback: Option<GapLaw>,
    /// (name as written, [`name_key`] of the name, μ table), like `gap_laws`.
    friction_tables: Vec<(String, u64, FrictionTable)>,
    friction_fallback: Option<FrictionTable>,
    /// (name as written, [`name_key`] of the name, heating law), like `friction_tables`.
    heat_laws: Vec<(String, u64, FrictionalHeat)>,
    heat_fallback: Option<FrictionalHeat>,
}

/// FNV-1a hash of a name's bytes, upper-cased: equal for names that match ignoring ASCII case.
#[inline]
fn name_key(name: &[u8]) -> u64 {
    name.iter().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b.to_ascii_uppercase())).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// A Fortran name without its trailing blank padding (and trailing NULs from C callers).
/// Skips eight blanks at a time: CHARACTER*80 names are mostly padding.
#[inline]
fn trim_fortran_name(name: &[u8]) -> &[u8] {
    const BLANKS: [u8; 8] = [b' '; 8];
    let mut end = name.len();
    while end >= 8 && name[end - 8..end] == BLANKS {
        end -= 8;
    }
    while end > 0 && (name[end - 1] == b' ' || name[end - 1] == 0) {
        end -= 1;
    }
    &name[..end]
}

/// Builds "file:line: key: message" from a byte span of the file.
struct Locator<'a> {
    path: &'a str,
    text: &'a str,
}

impl Locator<'_> {
    fn line(&self, span: std::ops::Range<usize>) -> usize {
        let end = span.start.min(self.text.len());
        self.text.as_bytes()[..end]
            .iter()
            .filter(|b| **b == b'\n')
            .count()
            + 1
    }

    fn error(&self, span: std::ops::Range<usize>, key: &str, message: &str) -> String {
        format!("{}:{}: {key}: {message}", self.path, self.line(span))
    }
}

impl Config {
    /// Parses and validates `text`; `path` is used in messages only.
    pub fn parse(path: &str, text: &str) -> Result<Config, String> {
        let at = Locator { path, text };
        let spec: FileSpec = toml::from_str(text).map_err(|e| {
            let line = e.span().map_or(0, |s| at.line(s));
            format!("{path}:{line}: {}", e.message())
        })?;
        let mut gap_laws: Vec<(String, GapLaw)> = Vec::new();
        let mut fallback = None;
        let mut friction_tables = Vec::new();
        let mut friction_fallback = None;
        let mut heat_laws = Vec::new();
        let mut heat_fallback = None;
        let mut names: Vec<&String> = Vec::new();
        for (name, entry) in &spec.interactions {
            let key = format!("interactions.{}", toml_key(name));
            let span = entry.span();
            let entry = entry.get_ref();
            if name != FALLBACK {
                if name.trim() != name || name.is_empty() {
                    return Err(at.error(
                        span,
                        &key,
                        "interaction names cannot be empty or begin or end with blanks",
                    ));
                }
                if let Some(other) = names.iter().find(|n| n.eq_ignore_ascii_case(name)) {
                    return Err(at.error(
                        span,
                        &key,
                        &format!("the same interaction as \"{other}\" (names match ignoring case)"),
                    ));
                }
                names.push(name);
            }
            if entry.conductance.is_none()
                && entry.radiation.is_none()
                && entry.friction.is_none()
                && entry.heat.is_none()
            {
                return Err(at.error(
                    span,
                    &key,
                    &format!(
                        "neither a thermal law nor a friction table; give [{key}.conductance], \
                         [{key}.radiation], [{key}.friction] and/or [{key}.heat]"
                    ),
                ));
            }
            if let Some(h) = &entry.heat {
                let law = frictional_heat(&at, &format!("{key}.heat"), h)?;
                if name == FALLBACK {
                    heat_fallback = Some(law);
                } else {
                    heat_laws.push((name.clone(), name_key(name.as_bytes()), law));
                }
            }
            if let Some(f) = &entry.friction {
                let table =
                    friction_table(&at, &format!("{key}.friction.table"), &f.get_ref().table)?;
                if name == FALLBACK {
                    friction_fallback = Some(table);
                } else {
                    friction_tables.push((name.clone(), name_key(name.as_bytes()), table));
                }
            }
            if entry.conductance.is_none() && entry.radiation.is_none() {
                continue;
            }
            let conduction = entry
                .conductance
                .as_ref()
                .map(|c| conduction(&at, &format!("{key}.conductance"), c))
                .transpose()?;
            let radiation = entry
                .radiation
                .as_ref()
                .map(|r| radiation(&at, &format!("{key}.radiation"), r))
                .transpose()?;
            let law = GapLaw::new(conduction, radiation).map_err(|e| {
                at.error(
                    span.clone(),
                    &key,
                    &format!("{e}; give [{key}.conductance] and/or [{key}.radiation]"),
                )
            })?;
            if name == FALLBACK {
                fallback = Some(law);
                continue;
            }
            gap_laws.push((name.clone(), law));
        }
        let gap_keys = gap_laws
            .iter()
            .map(|(n, _)| name_key(n.as_bytes()))
            .collect();
        Ok(Config {
            path: path.to_owned(),
            gap_laws,
            gap_keys,
            fallback,
            friction_tables,
            friction_fallback,
            heat_laws,
            heat_fallback,
        })
    }

    /// Reads and validates the file at `path`.
    pub fn load(path: &str) -> Result<Config, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{path}: cannot read the configuration file: {e}"))?;
        Config::parse(path, &text)
    }

    /// The file this configuration came from.
    #[must_use]
    pub fn path(&self) -> &str {
        &self.path
    }

    /// The thermal law of an interaction: exact name match after trimming trailing blanks,
    /// ignoring ASCII case (never by prefix), else the `"*"` entry.
    #[must_use]
    pub fn gap_law(&self, name: &[u8]) -> Option<&GapLaw> {
        let entries = self.gap_keys.iter().zip(&self.gap_laws);
        lookup(
            entries.map(|(k, (n, law))| (n.as_str(), *k, law)),
            name,
            self.fallback.as_ref(),
        )
    }
}

impl Config {
    /// The μ table of an interaction (`[interactions.NAME.friction]`), looked up as
    /// [`Config::gap_law`] does, else the `"*"` entry's.
    #[must_use]
    pub fn friction_table(&self, name: &[u8]) -> Option<&FrictionTable> {
        lookup(
            self.friction_tables
                .iter()
                .map(|(n, k, t)| (n.as_str(), *k, t)),
            name,
            self.friction_fallback.as_ref(),
        )
    }
}

impl Config {
    /// The frictional heating law of an interaction (`[interactions.NAME.heat]`), looked up as
    /// [`Config::gap_law`] does, else the `"*"` entry's.
    #[must_use]
    pub fn frictional_heat(&self, name: &[u8]) -> Option<&FrictionalHeat> {
        lookup(
            self.heat_laws.iter().map(|(n, k, h)| (n.as_str(), *k, h)),
            name,
            self.heat_fallback.as_ref(),
        )
    }
}

/// The value of `name` among `entries` (name as written, its [`name_key`], value): exact name
/// match after trimming trailing blanks, ignoring ASCII case (never by prefix; names are
/// compared only where the keys match), else `fallback`. The one lookup rule of every table.
#[inline]
fn lookup<'a, T: 'a>(
    mut entries: impl Iterator<Item = (&'a str, u64, &'a T)>,
    name: &[u8],
    fallback: Option<&'a T>,
) -> Option<&'a T> {
    let name = trim_fortran_name(name);
    let key = name_key(name);
    entries
        .find(|(n, k, _)| *k == key && n.as_bytes().eq_ignore_ascii_case(name))
        .map(|(_, _, value)| value)
        .or(fallback)
}

/// The μ table of `name` (a Fortran name) from the process-wide configuration, or why there is
/// none (the caller says which `PROPS` asked for it).
pub(crate) fn friction_table_for(name: &[u8]) -> Result<&'static FrictionTable, LawError> {
    interaction_entry(name, "a μ table", "friction", Config::friction_table)
}

/// The frictional heating law of `name` (a Fortran name) from the process-wide configuration,
/// or why there is none (`fricheat_`, the CalculiX variant's).
#[cfg(feature = "calculix")]
pub(crate) fn frictional_heat_for(name: &[u8]) -> Result<&'static FrictionalHeat, LawError> {
    interaction_entry(
        name,
        "*GAP HEAT GENERATION, USER",
        "heat",
        Config::frictional_heat,
    )
}

/// The entry `[interactions.NAME.section]` of interaction `name` (a Fortran name) that `find`
/// looks up in the process-wide configuration, or why there is none: no configuration file,
/// or no such entry (`what` says what asked for it).
fn interaction_entry<T: ?Sized>(
    name: &[u8],
    what: &str,
    section: &str,
    find: impl FnOnce(&'static Config, &[u8]) -> Option<&'static T>,
) -> Result<&'static T, LawError> {
    let cfg = global()
        .as_ref()
        .map_err(|m| LawError::Config(format!("{what} needs the configuration file: {m}")))?;
    find(cfg, name).ok_or_else(|| {
        let shown = String::from_utf8_lossy(trim_fortran_name(name));
        LawError::Parameter(format!(
            "{what} but {} has no [interactions.{}.{section}] (and no \"*\" entry)",
            cfg.path(),
            toml_key(&shown)
        ))
    })
}

/// Reads and validates a `[interactions.NAME.heat]` table: `fraction` required; the share as
/// `slave_share` or as both effusivities, not both forms; `speed` optional (absent: the host's
/// relative velocity). Errors point at the value's line.
fn frictional_heat(
    at: &Locator,
    key: &str,
    spec: &Spanned<HeatSpec>,
) -> Result<FrictionalHeat, String> {
    let h = spec.get_ref();
    let value = |v: &Option<Spanned<f64>>| v.as_ref().map(|s| (*s.get_ref(), s.span()));
    let Some((fraction, fraction_span)) = value(&h.fraction) else {
        return Err(at.error(
            spec.span(),
            &format!("{key}.fraction"),
            "required: η, the part of the frictional work turned into heat, in (0, 1]",
        ));
    };
    let share = value(&h.slave_share);
    let es = value(&h.slave_effusivity);
    let em = value(&h.master_effusivity);
    let (share, share_span) = match (share, es, em.clone()) {
        (Some((f, span)), None, None) => (HeatShare::Given(f), span),
        (None, Some((s, span)), Some((m, _))) => (
            HeatShare::Effusivities {
                slave: s,
                master: m,
            },
            span,
        ),
        (Some((_, span)), _, _) => {
            return Err(at.error(
                span,
                &format!("{key}.slave_share"),
                "give slave_share or the two effusivities, not both",
            ));
        }
        (None, Some((_, span)), None) | (None, None, Some((_, span))) => {
            return Err(at.error(
                span,
                key,
                "give both slave_effusivity and master_effusivity (√(k·ρ·c) of each body)",
            ));
        }
        (None, None, None) => {
            return Err(at.error(
                spec.span(),
                &format!("{key}.slave_share"),
                "required: the slave surface's part of the heat in [0, 1] (or \
                 slave_effusivity and master_effusivity)",
            ));
        }
    };
    let speed = value(&h.speed);
    let law = FrictionalHeat::new(
        fraction,
        share,
        speed
            .as_ref()
            .map_or(SlidingSpeed::FromHost, |(v, _)| SlidingSpeed::Given(*v)),
    );
    law.map_err(|e| {
        let m = strip_kind(&e);
        let (span, name) = if m.starts_with("fraction") {
            (fraction_span, "fraction")
        } else if m.starts_with("speed") {
            (speed.map_or_else(|| spec.span(), |(_, s)| s), "speed")
        } else if m.starts_with("master_effusivity") {
            (
                em.map_or_else(|| spec.span(), |(_, s)| s),
                "master_effusivity",
            )
        } else if m.starts_with("slave_effusivity") {
            (share_span, "slave_effusivity")
        } else {
            (share_span, "slave_share")
        };
        at.error(span, &format!("{key}.{name}"), &m)
    })
}

/// Reads and validates a `[μ, γ̇(, p(, θ̄))]` table; errors point at the row's line.
fn friction_table(
    at: &Locator,
    key: &str,
    table: &Spanned<Vec<Spanned<Vec<f64>>>>,
) -> Result<FrictionTable, String> {
    let rows: Vec<Vec<f64>> = table
        .get_ref()
        .iter()
        .map(|r| r.get_ref().clone())
        .collect();
    FrictionTable::new(&rows).map_err(|e| {
        let span = e
            .row
            .checked_sub(1)
            .and_then(|r| table.get_ref().get(r))
            .map_or_else(|| table.span(), Spanned::span);
        at.error(span, key, &e.message)
    })
}

/// The process-wide configuration, read once from `$INTERFACIAL_CONFIG` at first use.
pub(crate) fn global() -> &'static Result<Config, String> {
    static CONFIG: OnceLock<Result<Config, String>> = OnceLock::new();
    CONFIG.get_or_init(|| match std::env::var(CONFIG_ENV) {
        Ok(path) if !path.trim().is_empty() => Config::load(path.trim()),
        _ => Err(format!(
            "{CONFIG_ENV} is not set: name the TOML file that gives each interaction's \
             conductance law (see docs/config.md)"
        )),
    })
}

/// The thermal law of `name` (a Fortran name: blank-padded, any case) from the process-wide
/// configuration, or the error that explains why there is none.
pub(crate) fn gap_law_for(name: &[u8]) -> Result<&'static GapLaw, LawError> {
    let cfg = global().as_ref().map_err(|m| LawError::Config(m.clone()))?;
    cfg.gap_law(name).ok_or_else(|| {
        let shown = String::from_utf8_lossy(name);
        LawError::Parameter(format!(
            "interaction not found in {} (and no \"*\" entry); add [interactions.{}]",
            cfg.path(),
            toml_key(shown.trim_end())
        ))
    })
}

fn toml_key(name: &str) -> String {
    if !name.is_empty()
        && name
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-')
    {
        name.to_owned()
    } else {
        format!("\"{name}\"")
    }
}

/// The keys each conductance law accepts, besides `law`.
const LAW_KEYS: &[(&str, &[&str])] = &[
    ("constant", &["k"]),
    ("clearance-table", &["table"]),
    ("pressure-table", &["table"]),
    ("gas-gap", &["k_gas", "g0", "min_gap"]),
    ("cmy", &["c", "k_s", "m", "sigma", "H_c"]),
];

fn conduction(
    at: &Locator,
    key: &str,
    spec: &Spanned<ConductanceSpec>,
) -> Result<Conduction, String> {
    let c = spec.get_ref();
    let law = c.law.get_ref().as_str();
    let Some((_, allowed)) = LAW_KEYS.iter().find(|(name, _)| *name == law) else {
        let names: Vec<&str> = LAW_KEYS.iter().map(|(n, _)| *n).collect();
        return Err(at.error(
            c.law.span(),
            &format!("{key}.law"),
            &format!(
                "unknown law \"{law}\"; expected one of {}",
                names.join(", ")
            ),
        ));
    };
    let given: [(&str, Option<std::ops::Range<usize>>); 9] = [
        ("k", c.k.as_ref().map(Spanned::span)),
        ("table", c.table.as_ref().map(Spanned::span)),
        ("k_gas", c.k_gas.as_ref().map(Spanned::span)),
        ("g0", c.g0.as_ref().map(Spanned::span)),
        ("min_gap", c.min_gap.as_ref().map(Spanned::span)),
        ("c", c.c.as_ref().map(Spanned::span)),
        ("k_s", c.k_s.as_ref().map(Spanned::span)),
        ("m", c.m.as_ref().map(Spanned::span)),
        ("sigma", c.sigma.as_ref().map(Spanned::span)),
    ];
    let h_c_span = c.h_c.as_ref().map(Spanned::span);
    for (name, span) in given.iter().cloned().chain([("H_c", h_c_span)]) {
        if let Some(span) = span {
            if !allowed.contains(&name) {
                return Err(at.error(
                    span,
                    &format!("{key}.{name}"),
                    &format!(
                        "not a parameter of law \"{law}\" (it takes {})",
                        allowed.join(", ")
                    ),
                ));
            }
        }
    }
    let required = |v: &Option<Spanned<f64>>, name: &str| -> Result<f64, String> {
        v.as_ref().map(|s| *s.get_ref()).ok_or_else(|| {
            at.error(
                spec.span(),
                &format!("{key}.{name}"),
                &format!("law \"{law}\" needs {name}"),
            )
        })
    };
    // A value error points at the value's line when we know which value is at fault.
    let bad = |span: std::ops::Range<usize>, name: &str, e: LawError| {
        at.error(span, &format!("{key}.{name}"), &strip_kind(&e))
    };
    match law {
        "constant" => {
            let k = required(&c.k, "k")?;
            Conduction::constant(k).map_err(|e| bad(span_of(&c.k, spec), "k", e))
        }
        "clearance-table" | "pressure-table" => {
            let Some(table) = &c.table else {
                return Err(at.error(
                    spec.span(),
                    &format!("{key}.table"),
                    &format!("law \"{law}\" needs table = [[x, k], ...] or [[x, k, θ̄], ...]"),
                ));
            };
            let t = temperature_table(table.get_ref())
                .map_err(|m| at.error(table.span(), &format!("{key}.table"), &m))?;
            let made = if law == "clearance-table" {
                Conduction::clearance_table(t)
            } else {
                Conduction::pressure_table(t)
            };
            made.map_err(|e| bad(table.span(), "table", e))
        }
        "gas-gap" => {
            let k_gas = required(&c.k_gas, "k_gas")?;
            let g0 = c.g0.as_ref().map_or(0.0, |s| *s.get_ref());
            let min_gap = c.min_gap.as_ref().map_or(0.0, |s| *s.get_ref());
            Conduction::gas_gap(k_gas, g0, min_gap).map_err(|e| bad(spec.span(), "k_gas", e))
        }
        _ => {
            let cc = c.c.as_ref().map_or(CMY_DEFAULT_C, |s| *s.get_ref());
            Conduction::solid_spot(
                cc,
                required(&c.k_s, "k_s")?,
                required(&c.m, "m")?,
                required(&c.sigma, "sigma")?,
                required(&c.h_c, "H_c")?,
            )
            .map_err(|e| bad(spec.span(), "cmy", e))
        }
    }
}

fn span_of(v: &Option<Spanned<f64>>, whole: &Spanned<ConductanceSpec>) -> std::ops::Range<usize> {
    v.as_ref().map_or_else(|| whole.span(), Spanned::span)
}

fn strip_kind(e: &LawError) -> String {
    match e {
        LawError::Parameter(m)
        | LawError::Config(m)
        | LawError::Input(m)
        | LawError::Numerical(m) => m.clone(),
    }
}

fn temperature_table(rows: &[Vec<f64>]) -> Result<TemperatureTable, String> {
    let width = rows.first().map_or(2, Vec::len);
    if let Some(i) = rows.iter().position(|r| r.len() != width) {
        return Err(format!(
            "row {} has {} entries; every row needs {width}",
            i + 1,
            rows[i].len()
        ));
    }
    match width {
        2 => {
            let pairs: Vec<(f64, f64)> = rows.iter().map(|r| (r[0], r[1])).collect();
            Table1::new(&pairs)
                .map(TemperatureTable::constant_in_temperature)
                .map_err(|e| e.0)
        }
        3 => {
            let triples: Vec<(f64, f64, f64)> = rows.iter().map(|r| (r[0], r[1], r[2])).collect();
            TemperatureTable::new(&triples).map_err(|e| e.0)
        }
        n => Err(format!("rows have {n} entries; use [x, k] or [x, k, θ̄]")),
    }
}

fn radiation(at: &Locator, key: &str, spec: &Spanned<RadiationSpec>) -> Result<Radiation, String> {
    let r = spec.get_ref();
    // All three are required: no silent default for units.
    let get = |v: &Option<Spanned<f64>>, name: &str, what: &str| {
        v.as_ref().map(|s| (*s.get_ref(), s.span())).ok_or_else(|| {
            at.error(
                spec.span(),
                &format!("{key}.{name}"),
                &format!("required: {what}"),
            )
        })
    };
    let f = get(
        &r.view_factor,
        "view_factor",
        "F, effective emissivity × view factor",
    )?;
    let sigma = get(
        &r.stefan_boltzmann,
        "stefan_boltzmann",
        "σ in the model's units (5.670374419e-8 in SI)",
    )?;
    let zero = get(
        &r.absolute_zero,
        "absolute_zero",
        "absolute zero on the model's temperature scale (0 for kelvin, -273.15 for °C)",
    )?;
    Radiation::new(f.0, sigma.0, zero.0).map_err(|e| {
        let m = strip_kind(&e);
        let (span, name) = if m.starts_with("view_factor") {
            (f.1, "view_factor")
        } else if m.starts_with("stefan_boltzmann") {
            (sigma.1, "stefan_boltzmann")
        } else {
            (zero.1, "absolute_zero")
        };
        at.error(span, &format!("{key}.{name}"), &m)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Config, String> {
        Config::parse("test.toml", text)
    }

    #[test]
    fn the_issue_example_parses_and_matches_names_exactly() {
        let cfg = parse(
            r#"
[interactions.SI1.conductance]
law = "constant"
k = 2.0

[interactions."*".conductance]
law = "pressure-table"
table = [[0.0, 1.0], [100.0, 3.0]]
"#,
        )
        .unwrap();
        let k = |name: &str, p: f64| {
            cfg.gap_law(name.as_bytes())
                .unwrap()
                .evaluate(0.0, p, 20.0, 20.0)
                .unwrap()
                .k
        };
        assert_eq!(k("SI1", 50.0), 2.0);
        assert_eq!(k("si1      ", 50.0), 2.0);
        // SI1A is not SI1: it takes the fallback (k linear in p: 2 at p = 50).
        assert_eq!(k("SI1A", 50.0), 2.0);
        assert_eq!(k("SI1A", 100.0), 3.0);
        assert_eq!(k("OTHER", -5.0), 1.0);
        assert_eq!(k("OTHER", 500.0), 3.0);
    }

    #[test]
    fn lookup_trims_padding_ignores_case_and_never_matches_a_neighbour() {
        // Twenty names of one length that differ only in their last characters, each with its
        // own k = its number, and a fallback of k = 0.
        let mut text = String::new();
        for i in 1..=20 {
            text +=
                &format!("[interactions.int-{i:02}.conductance]\nlaw = \"constant\"\nk = {i}.0\n");
        }
        text += "[interactions.\"*\".conductance]\nlaw = \"constant\"\nk = 0.0\n";
        let cfg = parse(&text).unwrap();
        let k = |name: &[u8]| {
            cfg.gap_law(name)
                .unwrap()
                .evaluate(0.0, 1.0, 20.0, 20.0)
                .unwrap()
                .k
        };
        for i in 1..=20 {
            let base = format!("INT-{i:02}");
            for pad in [0, 1, 7, 8, 9, 16, 74] {
                let mut name = base.clone().into_bytes();
                name.resize(base.len() + pad, b' ');
                assert_eq!(k(&name), f64::from(i), "{base} + {pad} blanks");
                // C callers may pad with NULs, or end the blanks with one.
                let mut nul = name.clone();
                nul.push(0);
                assert_eq!(k(&nul), f64::from(i), "{base} + {pad} blanks + NUL");
            }
            assert_eq!(k(base.to_lowercase().as_bytes()), f64::from(i));
            // A prefix, an extension and a leading blank are other names: the fallback.
            assert_eq!(k(&base.as_bytes()[..5]), 0.0);
            assert_eq!(k(format!("{base}X").as_bytes()), 0.0);
            assert_eq!(k(format!(" {base}").as_bytes()), 0.0);
        }
        assert_eq!(k(b""), 0.0);
        assert_eq!(k(&[b' '; 80]), 0.0);
    }

    /// Every table refuses a key it does not know (`deny_unknown_fields`): a misspelt key in each, named
    /// with its line.
    #[test]
    fn every_table_refuses_an_unknown_key() {
        for (text, line, key) in [
            ("interaction = 1\n", 1, "interaction"),
            ("[interactions.A]\nconductivity = 1\n", 2, "conductivity"),
            (
                "[interactions.A.conductance]\nlaw = \"constant\"\nkk = 2.0\n",
                3,
                "kk",
            ),
            (
                "[interactions.A.radiation]\nview_factor = 0.5\nstefan = 1.0\n",
                3,
                "stefan",
            ),
            (
                "[interactions.A.friction]\ntable = [[0.3]]\ntabel = 1\n",
                3,
                "tabel",
            ),
        ] {
            let e = parse(text).unwrap_err();
            assert!(
                e.contains("unknown field") && e.contains(key) && e.contains(&format!(":{line}")),
                "{text}: {e}"
            );
        }
    }

    #[test]
    fn errors_name_file_line_and_key() {
        for (text, line, needle) in [
            (
                "[interactions.A.conductance]\nlaw = \"constant\"\nk = -1.0\n",
                3,
                "interactions.A.conductance.k",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"magic\"\n",
                2,
                "unknown law",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"pressure-table\"\ntable = [[1.0, 1.0], [0.0, 2.0]]\n",
                3,
                "increasing",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"pressure-table\"\ntable = []\n",
                3,
                "empty",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"pressure-table\"\ntable = [[0.0, -1.0]]\n",
                3,
                "negative",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"constant\"\n",
                1,
                "needs k",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"constant\"\nk = 1.0\ntable = [[0.0, 1.0]]\n",
                4,
                "not a parameter",
            ),
            (
                "[interactions.A.conductance]\nlaw = \"constant\"\nkk = 1.0\n",
                3,
                "kk",
            ),
            ("[interactions.A]\n", 1, "neither"),
            (
                "[interactions.A.conductance]\nlaw = \"constant\"\nk = 1\n[interactions.a.conductance]\nlaw = \"constant\"\nk = 2\n",
                4,
                "ignoring case",
            ),
            ("[interactions.A.conductance\n", 1, ""),
            (
                "[interactions.A.radiation]\nview_factor = 1.0\nstefan_boltzmann = 0.0\nabsolute_zero = 0.0\n",
                3,
                "stefan_boltzmann",
            ),
        ] {
            let e = parse(text).unwrap_err();
            assert!(e.starts_with(&format!("test.toml:{line}:")), "{e}");
            assert!(e.contains(needle), "{e}");
        }
    }
}
