//! The `PROPS` layouts as a tool can ask for them (`ifl_props_*`): per law, each entry's index,
//! key, symbol, unit, default and meaning, read from the laws' one description
//! (`props::schema::Layout::table_rows`, the rows docs/props.md's tables are rendered from), and
//! a check of a `PROPS` array without an increment that answers with `fric_`'s own refusal.

use std::ffi::{CStr, CString, c_char, c_int};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::OnceLock;

use super::native::IflStatus;
use super::{boundary, count, slice};
use crate::LawError;
use crate::config::friction_table_for;
use crate::props::schema::Layout;
use crate::props::{LAYOUTS, friction_law_with_table};
use crate::report::Site;

/// One row of a law's `PROPS` table (docs/props.md), as `ifl_props_entry` writes it. Every text
/// is NUL-terminated UTF-8 in static storage: valid for the program's life, never freed. An
/// entry whose meaning depends on another entry (law 1's `PROPS(14..16)` under steady-state
/// transport) has one row per meaning, `when` saying which holds.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct IflPropsEntry {
    /// `PROPS(index)`, numbered from 1 as in Fortran.
    pub index: c_int,
    /// The entry's name: the builders' and the decks' key, the seed's own name when
    /// `seed_name` is 1.
    pub key: *const c_char,
    /// 1 when `key` is the seed's parameter name, else 0.
    pub seed_name: c_int,
    /// The symbol ("μ_s"), or "" for none.
    pub symbol: *const c_char,
    /// The unit (dimension: "stress", "1/time"), or "" for a pure number.
    pub unit: *const c_char,
    /// What the entry is, with what each value of a switch means and a note.
    pub meaning: *const c_char,
    /// What 0 or absent means, in words ("0.005", "μ₂ = μ", "— (required)").
    pub default_text: *const c_char,
    /// The number 0 or absent stands for, when it is one number; NaN otherwise (the entry is
    /// required, or its default is another entry or a function of one: see `default_text`).
    pub default_value: f64,
    /// 1 when the entry must be given (`NPROPS` must reach it) where this row holds, else 0.
    pub required: c_int,
    /// The values it accepts, with the rules that tie it to other entries.
    pub valid: *const c_char,
    /// When this meaning holds: "PROPS(7) = 3", "PROPS(7) ≠ 3", or "" for always.
    pub when: *const c_char,
}

/// A row's texts, kept for the program's life (the pointers handed out point into them).
struct RowText {
    key: CString,
    symbol: CString,
    unit: CString,
    meaning: CString,
    default_text: CString,
    valid: CString,
    when: CString,
}

/// The texts of every law's rows, built on the first question.
fn rows() -> &'static [Vec<(IflPropsEntryValues, RowText)>; LAYOUTS.len()] {
    static ROWS: OnceLock<[Vec<(IflPropsEntryValues, RowText)>; LAYOUTS.len()]> = OnceLock::new();
    ROWS.get_or_init(|| LAYOUTS.map(law_rows))
}

/// The numbers of a row (the texts are in [`RowText`]).
#[derive(Clone, Copy)]
struct IflPropsEntryValues {
    index: c_int,
    seed_name: c_int,
    default_value: f64,
    required: c_int,
}

fn text(s: &str) -> CString {
    // Our own texts hold no NUL; one would be shown as a blank rather than cut the text.
    CString::new(s.replace('\0', " ")).unwrap_or_default()
}

fn law_rows(layout: &Layout) -> Vec<(IflPropsEntryValues, RowText)> {
    layout
        .table_rows()
        .into_iter()
        .map(|row| {
            let e = row.entry;
            (
                IflPropsEntryValues {
                    index: c_int::try_from(e.index).unwrap_or(c_int::MAX),
                    seed_name: c_int::from(e.seed_name),
                    default_value: row.default_value.unwrap_or(f64::NAN),
                    // Required by the layout, or in this row's meaning (0 is not a value of
                    // the entry: steady transport's ω).
                    required: c_int::from(
                        matches!(e.default, crate::props::schema::Default::Required)
                            || !e.class.admits(0.0),
                    ),
                },
                RowText {
                    key: text(e.key),
                    symbol: text(e.symbol),
                    unit: text(e.unit),
                    meaning: text(&row.meaning),
                    default_text: text(&row.default),
                    valid: text(&row.valid),
                    when: text(&row.when_text()),
                },
            )
        })
        .collect()
}

/// The position in [`LAYOUTS`] of the law with code `law` (`PROPS(1)`).
fn law_position(law: c_int) -> Option<usize> {
    LAYOUTS.iter().position(|l| l.code == law)
}

/// How many laws `ifl_props_law_code` lists (3: Coulomb, adhesive and rate-and-state friction).
#[unsafe(no_mangle)]
pub extern "C" fn ifl_props_law_count() -> c_int {
    LAYOUTS.len() as c_int
}

/// The law code (`PROPS(1)`) of the `i`-th law, `i` from 0 to `ifl_props_law_count() - 1`;
/// 0 for any other `i`.
#[unsafe(no_mangle)]
pub extern "C" fn ifl_props_law_code(i: c_int) -> c_int {
    usize::try_from(i)
        .ok()
        .and_then(|i| LAYOUTS.get(i))
        .map_or(0, |l| l.code)
}

/// The number of rows of law `law`'s `PROPS` table (`law` is the code `PROPS(1)`, one of
/// `ifl_props_law_code`'s): one per entry, plus one per other meaning of an entry (`when`).
/// 0 for a code that is not a law's.
#[unsafe(no_mangle)]
pub extern "C" fn ifl_props_entry_count(law: c_int) -> c_int {
    law_position(law).map_or(0, |p| {
        c_int::try_from(rows()[p].len()).unwrap_or(c_int::MAX)
    })
}

/// Writes row `i` (from 0 to `ifl_props_entry_count(law) - 1`, in docs/props.md's order) of law
/// `law`'s `PROPS` table into `*out` and returns `IFL_STATUS_OK`. An unknown law or a row out of
/// range is `IFL_STATUS_BAD_PARAMETER`, a NULL `out` `IFL_STATUS_BAD_INPUT`; both are reported
/// like any failure (`ifl_last_error`) and leave `*out` as it was.
///
/// # Safety
/// `out` is NULL or points to a writable `IflPropsEntry`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ifl_props_entry(
    law: c_int,
    i: c_int,
    out: *mut IflPropsEntry,
) -> IflStatus {
    boundary(
        || Site {
            routine: "ifl_props_entry",
            interaction: String::new(),
            place: format!("law {law}, row {i}"),
        },
        || {
            let p = law_position(law).ok_or_else(|| {
                let codes: Vec<String> = LAYOUTS
                    .iter()
                    .map(|l| format!("{}: {}", l.code, l.law))
                    .collect();
                LawError::Parameter(format!(
                    "law {law} is not a law code ({})",
                    codes.join(", ")
                ))
            })?;
            let (v, t) = usize::try_from(i)
                .ok()
                .and_then(|i| rows()[p].get(i))
                .ok_or_else(|| {
                    LawError::Parameter(format!(
                        "row {i} is out of range: law {law} has rows 0 to {}",
                        rows()[p].len() - 1
                    ))
                })?;
            if out.is_null() {
                return Err(super::null_pointer("out"));
            }
            let entry = IflPropsEntry {
                index: v.index,
                key: t.key.as_ptr(),
                seed_name: v.seed_name,
                symbol: t.symbol.as_ptr(),
                unit: t.unit.as_ptr(),
                meaning: t.meaning.as_ptr(),
                default_text: t.default_text.as_ptr(),
                default_value: v.default_value,
                required: v.required,
                valid: t.valid.as_ptr(),
                when: t.when.as_ptr(),
            };
            // SAFETY: non-NULL and writable per the contract.
            unsafe { out.write(entry) };
            Ok(())
        },
        || {},
    )
    .into()
}

/// Checks a `PROPS` array of `nprops` entries as `fric_` reads it, without an increment, for
/// the interaction named `interaction` (NUL-terminated, as `CINAME` without its blanks; NULL
/// for a blank name), whose μ table `PROPS(8) = 2` reads from `INTERFACIAL_CONFIG` as `fric_`
/// does. Returns `IFL_STATUS_OK` when `fric_` would take it, otherwise the status and, in
/// `message`, the cause `fric_` would report, word for word ("bad parameter: PROPS(2): …", the
/// part after the interaction and the place in `fric_`'s line).
///
/// `message` (capacity `capacity` bytes) receives the text NUL-terminated, truncated to fit
/// (nothing past `capacity` is written; nothing at all when `message` is NULL or `capacity` is
/// 0); "" when `PROPS` is fine. `*message_len`, when `message_len` is not NULL, receives the
/// whole text's length in bytes without the NUL. A question, not a failure: nothing is printed
/// and the thread's last error is left as it was.
///
/// # Safety
/// `props` is NULL or points to `nprops` readable doubles; `interaction` is NULL or
/// NUL-terminated; `message` is NULL or points to `capacity` writable bytes; `message_len` is
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ifl_props_check(
    props: *const f64,
    nprops: c_int,
    interaction: *const c_char,
    message: *mut c_char,
    capacity: usize,
    message_len: *mut usize,
) -> IflStatus {
    let verdict = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: as the contract above.
        unsafe { check(props, nprops, interaction) }
    }));
    let (status, text) = match verdict {
        Ok(Ok(())) => (IflStatus::Ok, String::new()),
        Ok(Err(e)) => (status_of(&e), e.to_string()),
        Err(_) => (
            IflStatus::InternalError,
            "internal error (panic in ifl_props_check); please report it".to_string(),
        ),
    };
    // SAFETY: as the contract above.
    unsafe { copy_text(&text, message, capacity, message_len) };
    status
}

/// `fric_`'s reading of `NPROPS` and `PROPS` (src/abi/fric.rs, `FricArgs::run`): the count,
/// the array, then the `PROPS` layer's reader with the interaction's μ table when the law asks
/// for one (`props::friction_law_with_table`, as `fric_`). The agreement with `fric_` is a property test (tests/props_query.rs).
///
/// # Safety
/// As [`ifl_props_check`].
unsafe fn check(
    props: *const f64,
    nprops: c_int,
    interaction: *const c_char,
) -> Result<(), LawError> {
    let nprops = count("NPROPS", nprops)?;
    // SAFETY: `nprops` readable doubles per the contract.
    let props = unsafe { slice(props, nprops, "PROPS") }?;
    // The law's own description says whether it needs the interaction's μ table.
    friction_law_with_table(props, || {
        let name: &[u8] = if interaction.is_null() {
            &[]
        } else {
            // SAFETY: NUL-terminated per the contract.
            unsafe { CStr::from_ptr(interaction) }.to_bytes()
        };
        friction_table_for(name)
    })?;
    Ok(())
}

/// The status `fric_`'s refusal maps to (as the native calls map it).
fn status_of(e: &LawError) -> IflStatus {
    match e {
        LawError::Parameter(_) | LawError::Config(_) => IflStatus::BadParameter,
        LawError::Input(_) => IflStatus::BadInput,
        LawError::Numerical(_) => IflStatus::NumericalFailure,
    }
}

/// Copies `text` into `buf` (capacity `capacity`, NUL-terminated, truncated to fit without
/// cutting a UTF-8 character) and its whole length into `*len`.
///
/// # Safety
/// `buf` is NULL or points to `capacity` writable bytes; `len` is NULL or writable.
pub(crate) unsafe fn copy_text(text: &str, buf: *mut c_char, capacity: usize, len: *mut usize) {
    if !buf.is_null() && capacity > 0 {
        let mut n = text.len().min(capacity - 1);
        while !text.is_char_boundary(n) {
            n -= 1;
        }
        // SAFETY: n + 1 ≤ capacity writable bytes; the source is our own string.
        unsafe {
            std::ptr::copy_nonoverlapping(text.as_ptr().cast::<c_char>(), buf, n);
            buf.add(n).write(0);
        }
    }
    if !len.is_null() {
        // SAFETY: writable per the contract.
        unsafe { len.write(text.len()) };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_message_is_cut_to_the_buffer_and_never_past_it() {
        let mut buf = [b'x' as c_char; 8];
        let mut len = 0usize;
        unsafe { copy_text("μ_s = -1", buf.as_mut_ptr(), 4, &mut len) };
        assert_eq!(len, "μ_s = -1".len());
        // "μ" is two bytes: 3 bytes of room take "μ_" and the NUL, nothing after.
        let got: Vec<u8> = buf.iter().map(|&c| c as u8).collect();
        assert_eq!(&got, &[0xce, 0xbc, b'_', 0, b'x', b'x', b'x', b'x']);
        // Room for the first byte of "μ" only: the character is not cut.
        unsafe { copy_text("μ", buf.as_mut_ptr(), 2, std::ptr::null_mut()) };
        assert_eq!(buf[0], 0);
        assert_eq!(buf[1] as u8, 0xbc, "the byte after the NUL is left alone");
        // NULL buffer: the length alone.
        unsafe { copy_text("abc", std::ptr::null_mut(), 0, &mut len) };
        assert_eq!(len, 3);
    }
}
