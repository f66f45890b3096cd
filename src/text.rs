//! Untrusted text in messages: words from a scene file or a flag are shown escaped (no
//! terminal control characters, no NUL) and truncated (a 60,000-digit number is not echoed
//! whole), so an error message is always one readable line per line it meant to have.

/// Longest run of non-blank characters [`quote`] shows whole (one token of a scene file or a
/// flag); longer ones keep their start and say how long they were.
const MAX_WORD: usize = 64;
/// The same for a word of a whole message ([`sanitize`]): as long as a path may be (Linux's
/// PATH_MAX), since a message's words include the paths of the files it is about, which a user
/// needs whole; the tokens inside it were quoted to `MAX_WORD` where the message was made.
const MAX_MESSAGE_WORD: usize = 4096;
/// Characters of a long word that are kept.
const KEEP: usize = 32;
/// Longest message shown whole (in characters).
const MAX_MESSAGE: usize = 4096;

/// `s` with control characters escaped (`\0`, `\u{1b}`, ...; tabs and newlines too) and
/// truncated to `MAX_WORD` characters, for quoting one untrusted token.
pub fn quote(s: &str) -> String {
    let mut out = String::new();
    let n = s.chars().count();
    for c in s.chars().take(if n > MAX_WORD { KEEP } else { n }) {
        push_escaped(&mut out, c, true);
    }
    if n > MAX_WORD {
        out.push_str(&format!("... ({n} characters)"));
    }
    out
}

/// A whole message made safe to print: control characters other than newlines escaped, every
/// word longer than `MAX_MESSAGE_WORD` characters truncated, the whole at most `MAX_MESSAGE`
/// characters.
pub fn sanitize(msg: &str) -> String {
    let mut out = String::new();
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        let n = word.chars().count();
        if n > MAX_MESSAGE_WORD {
            out.extend(word.chars().take(KEEP));
            out.push_str(&format!("... ({n} characters)"));
        } else {
            out.push_str(word);
        }
        word.clear();
    };
    for c in msg.chars() {
        if c == ' ' || c == '\n' {
            flush(&mut word, &mut out);
            out.push(c);
        } else {
            push_escaped(&mut word, c, false);
        }
    }
    flush(&mut word, &mut out);
    if out.chars().count() > MAX_MESSAGE {
        let total = out.chars().count();
        out = out.chars().take(MAX_MESSAGE).collect::<String>() + &format!("... ({total} characters)");
    }
    out
}

/// A file's path for a message: control characters escaped (tabs and newlines too), nothing
/// truncated, since the path is what a user needs whole to find the file.
pub fn path(p: &std::path::Path) -> String {
    let mut out = String::new();
    for c in p.display().to_string().chars() {
        push_escaped(&mut out, c, true);
    }
    out
}

fn push_escaped(out: &mut String, c: char, escape_whitespace: bool) {
    if c.is_control() && (escape_whitespace || c != '\t') {
        out.extend(c.escape_default());
    } else {
        out.push(c);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped() {
        assert_eq!(quote("a\0b\x1b[2Jc"), "a\\u{0}b\\u{1b}[2Jc");
        assert_eq!(sanitize("line 1\nbad \x07bell"), "line 1\nbad \\u{7}bell");
        assert_eq!(quote("plain 1.5"), "plain 1.5");
        let long = format!("/scenes/{}/a\0b\x1b[2J.mtl", "d".repeat(100));
        assert_eq!(path(std::path::Path::new(&long)), long.replace('\0', "\\u{0}").replace('\x1b', "\\u{1b}"));
    }

    #[test]
    fn long_words_are_truncated() {
        let digits = "9".repeat(60_000);
        let q = quote(&digits);
        assert!(q.starts_with(&"9".repeat(KEEP)) && q.ends_with("... (60000 characters)"), "{q}");
        let s = sanitize(&format!("x.mtl:3: '{digits}' is not a finite number"));
        assert!(s.len() < 200 && s.ends_with("is not a finite number"), "{s}");
        assert!(sanitize(&"word ".repeat(5000)).chars().count() < MAX_MESSAGE + 40);
        // A path, however deep, stays whole in a message.
        let path = format!("/{}/scene.mtl:3:", "d".repeat(300));
        assert_eq!(sanitize(&format!("{path} bad")), format!("{path} bad"));
    }
}
