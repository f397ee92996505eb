//! The checks the tests of refused input share (bad_input.rs, fric_abi.rs, last_error.rs;
//! included there by path): a message must name each of the given words (the entry point, the
//! interaction, the cause), and a refused `fric_` call leaves the host's arrays as they were.
// Each test file uses its own subset.
#![allow(dead_code)]

use interfacial::CUTBACK_RATIO;
use interfacial_test_hosts::FricCall;

/// Asserts that `msg` contains every one of `words`; `context` says which case it was.
#[track_caller]
pub fn assert_mentions(msg: &str, words: &[&str], context: &str) {
    for word in words {
        assert!(
            msg.contains(word),
            "{context}: the message {msg:?} does not name {word:?}"
        );
    }
}

/// Makes the `fric_` call `c` (interaction 'SI1') and asserts that it was refused as the contract
/// says: PNEWDT = [`CUTBACK_RATIO`], LM, TAU and STATEV as they were to the bit, and a message
/// naming FRIC, 'SI1' and `word`. Returns the call for the caller's further checks.
#[track_caller]
pub fn assert_fric_refused(mut c: FricCall, what: &str, word: &str) -> FricCall {
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let before = c.clone();
    c.call();
    assert_eq!(c.pnewdt, CUTBACK_RATIO, "{what}: PNEWDT");
    assert_eq!(c.lm, before.lm, "{what}: LM");
    assert_eq!(bits(&c.tau), bits(&before.tau), "{what}: TAU");
    assert_eq!(bits(&c.statev), bits(&before.statev), "{what}: STATEV");
    assert_mentions(&FricCall::last_error(), &["FRIC", "'SI1'", word], what);
    c
}
