//! A small SDL tokenizer for running text macros token by token.
//!
//! In: SDL text and a byte position. Out: the next token (string, number, word, `#`
//! directive or punctuation) with its byte range, skipping whitespace and comments. Holds:
//! positions are byte offsets into the text; every token is at least one byte long.

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokenKind {
    /// A quoted string, quotes included.
    String,
    /// A number such as `1`, `2.5`, `.5` or `1e-3`.
    Number,
    /// An identifier or keyword.
    Word,
    /// A directive: `#` and a directive word (possibly spaced, `# end`).
    Directive,
    /// Any other character (`{`, `,`, `<`, ...).
    Punctuation,
}

/// One token: its kind and byte range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    /// What it is.
    pub kind: TokenKind,
    /// Offset of its first byte.
    pub start: usize,
    /// Offset just past its last byte.
    pub end: usize,
}

impl Token {
    /// The token's text.
    pub fn text<'t>(&self, source: &'t str) -> &'t str {
        &source[self.start..self.end]
    }

    /// For a directive, its word (`if`, `end`, ...); empty otherwise.
    pub fn directive_word<'t>(&self, source: &'t str) -> &'t str {
        if self.kind != TokenKind::Directive {
            return "";
        }
        source[self.start + 1..self.end].trim_start_matches([' ', '\t'])
    }
}

/// The words that make `#word` a directive (any other `#` is ignored, as in POV-Ray).
pub(crate) const DIRECTIVE_WORDS: &[&str] = &[
    "declare", "local", "undef", "ifdef", "ifndef", "if", "elseif", "else", "end", "while", "for",
    "switch", "case", "range", "break", "macro", "include", "version", "default", "debug",
    "warning", "error", "fopen", "fclose", "read", "write",
];

fn is_word_byte(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || byte == b'_'
}

/// The end of the word starting at `start` (`start` itself when there is none).
fn word_end(bytes: &[u8], start: usize) -> usize {
    let mut end = start;
    if end < bytes.len() && (bytes[end].is_ascii_alphabetic() || bytes[end] == b'_') {
        while end < bytes.len() && is_word_byte(bytes[end]) {
            end += 1;
        }
    }
    end
}

/// Skips whitespace, comments and `#` signs that start no directive from `position`.
pub fn skip_trivia(text: &str, mut position: usize) -> usize {
    let bytes = text.as_bytes();
    while position < bytes.len() {
        match bytes[position] {
            b' ' | b'\t' | b'\r' | b'\n' | 0x0c | 0x1a => position += 1,
            b'/' if bytes.get(position + 1) == Some(&b'/') => {
                while position < bytes.len() && !matches!(bytes[position], b'\n' | b'\r') {
                    position += 1;
                }
            }
            b'/' if bytes.get(position + 1) == Some(&b'*') => {
                position = block_comment_end(bytes, position);
            }
            b'#' if directive_end(text, position).is_none() => position += 1,
            _ if text[position..].starts_with('\u{feff}') => position += '\u{feff}'.len_utf8(),
            _ => break,
        }
    }
    position
}

/// The end of the (nested) block comment starting at `start`.
fn block_comment_end(bytes: &[u8], start: usize) -> usize {
    let mut depth = 0usize;
    let mut position = start;
    while position < bytes.len() {
        if bytes[position] == b'/' && bytes.get(position + 1) == Some(&b'*') {
            depth += 1;
            position += 2;
        } else if bytes[position] == b'*' && bytes.get(position + 1) == Some(&b'/') {
            depth -= 1;
            position += 2;
            if depth == 0 {
                return position;
            }
        } else {
            position += 1;
        }
    }
    bytes.len()
}

/// The end of the directive whose `#` is at `start`, or `None` when no directive word follows.
fn directive_end(text: &str, start: usize) -> Option<usize> {
    let bytes = text.as_bytes();
    let mut word_start = start + 1;
    while word_start < bytes.len() && matches!(bytes[word_start], b' ' | b'\t') {
        word_start += 1;
    }
    let end = word_end(bytes, word_start);
    DIRECTIVE_WORDS
        .contains(&&text[word_start..end])
        .then_some(end)
}

/// The token starting at or after `position` (after trivia), or `None` at the end.
pub fn next_token(text: &str, position: usize) -> Option<Token> {
    let bytes = text.as_bytes();
    let start = skip_trivia(text, position);
    let first = *bytes.get(start)?;
    let (kind, end) = match first {
        b'"' => {
            let mut end = start + 1;
            while end < bytes.len() && bytes[end] != b'"' {
                end += if bytes[end] == b'\\' { 2 } else { 1 };
            }
            (TokenKind::String, (end + 1).min(bytes.len()))
        }
        b'#' => (
            TokenKind::Directive,
            directive_end(text, start).unwrap_or(start + 1),
        ),
        b'0'..=b'9' => (TokenKind::Number, number_end(bytes, start)),
        b'.' if bytes.get(start + 1).is_some_and(u8::is_ascii_digit) => {
            (TokenKind::Number, number_end(bytes, start))
        }
        _ if first.is_ascii_alphabetic() || first == b'_' => {
            (TokenKind::Word, word_end(bytes, start))
        }
        _ => {
            let length = text[start..].chars().next().map_or(1, char::len_utf8);
            (TokenKind::Punctuation, start + length)
        }
    };
    Some(Token { kind, start, end })
}

/// The end of the number starting at `start`.
fn number_end(bytes: &[u8], start: usize) -> usize {
    let digits = |mut position: usize| {
        while position < bytes.len() && bytes[position].is_ascii_digit() {
            position += 1;
        }
        position
    };
    let mut end = digits(start);
    if bytes.get(end) == Some(&b'.') {
        end = digits(end + 1);
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        let mut exponent = end + 1;
        if matches!(bytes.get(exponent), Some(b'+' | b'-')) {
            exponent += 1;
        }
        if bytes.get(exponent).is_some_and(u8::is_ascii_digit) {
            end = digits(exponent);
        }
    }
    end
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tokens(text: &str) -> Vec<(TokenKind, &str)> {
        let mut position = 0;
        let mut found = Vec::new();
        while let Some(token) = next_token(text, position) {
            found.push((token.kind, token.text(text)));
            position = token.end;
        }
        found
    }

    #[test]
    fn splits_sdl_into_tokens() {
        use TokenKind::*;
        assert_eq!(
            tokens("#if(A) \"a\\\"b\", P[J] // c\n # end /* x */ 1.5e-3 .5 <=#"),
            vec![
                (Directive, "#if"),
                (Punctuation, "("),
                (Word, "A"),
                (Punctuation, ")"),
                (String, "\"a\\\"b\""),
                (Punctuation, ","),
                (Word, "P"),
                (Punctuation, "["),
                (Word, "J"),
                (Punctuation, "]"),
                (Directive, "# end"),
                (Number, "1.5e-3"),
                (Number, ".5"),
                (Punctuation, "<"),
                (Punctuation, "="),
            ]
        );
    }

    #[test]
    fn directive_words_skip_spaces() {
        let text = "#  else";
        let token = next_token(text, 0).expect("a token");
        assert_eq!(token.directive_word(text), "else");
    }
}
