//! The check the tests of refused input share: a message must name each of the given words (the
//! entry point, the interaction, the cause), and a failure prints the whole message.

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
