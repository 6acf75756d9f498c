//! Interned identifier names.
//!
//! In: identifier text, from the parser or from the evaluator (names built at run time, such
//! as `Parse_String` files). Out: a [`Symbol`], one machine word, equal for equal text.
//! Holds: every distinct text is stored once for the life of the process and keeps its
//! dense number ([`Symbol::index`]), so symbol tables can be plain arrays and comparing two
//! names never reads their characters.

use std::collections::HashMap;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::Deref;
use std::sync::{Mutex, OnceLock};

/// An interned name: compares, hashes and copies as a pointer, reads as its text.
#[derive(Clone, Copy)]
pub struct Symbol(&'static Entry);

/// What one interned name holds.
struct Entry {
    index: u32,
    text: &'static str,
}

/// Every name interned so far, by its text.
fn table() -> &'static Mutex<HashMap<&'static str, &'static Entry>> {
    static TABLE: OnceLock<Mutex<HashMap<&'static str, &'static Entry>>> = OnceLock::new();
    TABLE.get_or_init(|| Mutex::new(HashMap::new()))
}

impl Symbol {
    /// The symbol of `text`, creating it on first use.
    pub fn intern(text: &str) -> Symbol {
        // A poisoned lock still holds a consistent table: entries are only ever added whole.
        let mut table = table()
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        if let Some(entry) = table.get(text) {
            return Symbol(entry);
        }
        let index = u32::try_from(table.len()).expect("fewer than 2^32 distinct names");
        let text: &'static str = Box::leak(text.to_owned().into_boxed_str());
        let entry: &'static Entry = Box::leak(Box::new(Entry { index, text }));
        table.insert(text, entry);
        Symbol(entry)
    }

    /// The name's text.
    pub fn as_str(self) -> &'static str {
        self.0.text
    }

    /// A small number unique to this name (names are numbered from 0 as they are first
    /// interned), for indexing tables by name.
    pub fn index(self) -> usize {
        self.0.index as usize
    }
}

impl PartialEq for Symbol {
    fn eq(&self, other: &Symbol) -> bool {
        std::ptr::eq(self.0, other.0)
    }
}

impl Eq for Symbol {}

impl Hash for Symbol {
    fn hash<H: Hasher>(&self, state: &mut H) {
        state.write_u32(self.0.index);
    }
}

impl PartialOrd for Symbol {
    fn partial_cmp(&self, other: &Symbol) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

/// Alphabetical, so sorted names do not depend on the order they were first met.
impl Ord for Symbol {
    fn cmp(&self, other: &Symbol) -> std::cmp::Ordering {
        self.as_str().cmp(other.as_str())
    }
}

impl Deref for Symbol {
    type Target = str;

    fn deref(&self) -> &str {
        self.0.text
    }
}

impl AsRef<str> for Symbol {
    fn as_ref(&self) -> &str {
        self.0.text
    }
}

impl From<&str> for Symbol {
    fn from(text: &str) -> Symbol {
        Symbol::intern(text)
    }
}

impl From<&Symbol> for Symbol {
    fn from(symbol: &Symbol) -> Symbol {
        *symbol
    }
}

impl From<String> for Symbol {
    fn from(text: String) -> Symbol {
        Symbol::intern(&text)
    }
}

impl PartialEq<str> for Symbol {
    fn eq(&self, other: &str) -> bool {
        self.0.text == other
    }
}

impl PartialEq<&str> for Symbol {
    fn eq(&self, other: &&str) -> bool {
        self.0.text == *other
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0.text)
    }
}

impl fmt::Debug for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.0.text, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_text_gives_the_same_symbol() {
        let a = Symbol::intern("Symbol_Test_Name");
        let b = Symbol::from(String::from("Symbol_Test_Name"));
        assert_eq!(a, b);
        assert_eq!(a.index(), b.index());
        assert_eq!(a.as_str(), "Symbol_Test_Name");
        assert_eq!(&*a, "Symbol_Test_Name");
    }

    #[test]
    fn different_text_gives_different_symbols_in_text_order() {
        let a = Symbol::intern("Symbol_Test_B");
        let b = Symbol::intern("Symbol_Test_A");
        assert_ne!(a, b);
        assert_ne!(a.index(), b.index());
        assert!(b < a, "ordering follows the text, not the interning order");
        assert_eq!(format!("{a} {b:?}"), "Symbol_Test_B \"Symbol_Test_A\"");
    }

    #[test]
    fn symbols_are_shared_across_threads() {
        let here = Symbol::intern("Symbol_Test_Thread");
        let there = std::thread::spawn(|| Symbol::intern("Symbol_Test_Thread"))
            .join()
            .expect("thread");
        assert_eq!(here, there);
    }
}
