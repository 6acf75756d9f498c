//! The stack of symbol tables, with an index from each name to the tables holding it.
//!
//! In: pushes and pops of tables (global, include file, macro call, function call) and
//! insertions and removals of names. Out: the innermost table holding a name, in constant
//! time however deep macro recursion goes. Holds: `holders[name]` lists exactly the tables
//! that contain `name`, in ascending order.

use super::value::Value;
use super::Scope;
use crate::hash::FastHash;
use std::collections::HashMap;
use std::rc::Rc;

/// Symbol tables, outermost (global) first.
pub(crate) struct ScopeStack {
    tables: Vec<Scope>,
    /// For each name, the indices of the tables that hold it, ascending.
    holders: HashMap<Rc<str>, Vec<usize>, FastHash>,
}

impl ScopeStack {
    /// A stack holding only an empty global table.
    pub(crate) fn new() -> ScopeStack {
        ScopeStack {
            tables: vec![Scope::default()],
            holders: HashMap::default(),
        }
    }

    /// Number of tables.
    pub(crate) fn len(&self) -> usize {
        self.tables.len()
    }

    /// Pushes a table (its names become visible, shadowing outer ones).
    pub(crate) fn push(&mut self, table: Scope) {
        let index = self.tables.len();
        for name in table.keys() {
            self.holders.entry(name.clone()).or_default().push(index);
        }
        self.tables.push(table);
    }

    /// Pops the innermost table; the global table is never popped.
    pub(crate) fn pop(&mut self) -> Option<Scope> {
        if self.tables.len() <= 1 {
            return None;
        }
        let table = self.tables.pop()?;
        let index = self.tables.len();
        for name in table.keys() {
            self.forget(name, index);
        }
        Some(table)
    }

    fn forget(&mut self, name: &str, index: usize) {
        if let Some(indices) = self.holders.get_mut(name) {
            if let Some(at) = indices.iter().rposition(|&i| i == index) {
                indices.remove(at);
            }
            if indices.is_empty() {
                self.holders.remove(name);
            }
        }
    }

    /// Stores `value` under `name` in table `index`.
    pub(crate) fn insert(&mut self, index: usize, name: Rc<str>, value: Value) {
        let Some(table) = self.tables.get_mut(index) else {
            return;
        };
        if let Some(slot) = table.get_mut(&name) {
            *slot = value;
            return;
        }
        let indices = self.holders.entry(name.clone()).or_default();
        let at = indices.partition_point(|&i| i < index);
        indices.insert(at, index);
        table.insert(name, value);
    }

    /// Removes `name` from table `index`, returning its value.
    pub(crate) fn remove(&mut self, index: usize, name: &str) -> Option<Value> {
        let value = self.tables.get_mut(index)?.remove(name)?;
        self.forget(name, index);
        Some(value)
    }

    /// The innermost table at or below `top` holding `name`.
    pub(crate) fn holder_at_or_below(&self, name: &str, top: usize) -> Option<usize> {
        let indices = self.holders.get(name)?;
        let at = indices.partition_point(|&i| i <= top);
        at.checked_sub(1).map(|i| indices[i])
    }

    /// The innermost table holding `name`.
    pub(crate) fn innermost_holder(&self, name: &str) -> Option<usize> {
        self.holders.get(name)?.last().copied()
    }

    /// The value of `name` in table `index`.
    pub(crate) fn get(&self, index: usize, name: &str) -> Option<&Value> {
        self.tables.get(index)?.get(name)
    }

    /// The value of `name` in table `index`, to change in place.
    pub(crate) fn get_mut(&mut self, index: usize, name: &str) -> Option<&mut Value> {
        self.tables.get_mut(index)?.get_mut(name)
    }

    /// Every name in every table (for suggestions).
    pub(crate) fn names(&self) -> impl Iterator<Item = &str> {
        self.holders.keys().map(|k| &**k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name(s: &str) -> Rc<str> {
        Rc::from(s)
    }

    #[test]
    fn inner_tables_shadow_outer_ones_until_popped() {
        let mut stack = ScopeStack::new();
        stack.insert(0, name("A"), Value::Float(1.0));
        let mut table = Scope::default();
        table.insert(name("A"), Value::Float(2.0));
        stack.push(table);
        assert_eq!(stack.innermost_holder("A"), Some(1));
        assert_eq!(stack.holder_at_or_below("A", 0), Some(0));
        stack.pop();
        assert_eq!(stack.innermost_holder("A"), Some(0));
    }

    #[test]
    fn inserting_into_an_outer_table_keeps_the_index_ordered() {
        let mut stack = ScopeStack::new();
        stack.push(Scope::default());
        stack.insert(1, name("B"), Value::Float(1.0));
        stack.insert(0, name("B"), Value::Float(2.0));
        assert_eq!(stack.innermost_holder("B"), Some(1));
        assert_eq!(stack.holder_at_or_below("B", 0), Some(0));
        assert!(stack.remove(1, "B").is_some());
        assert_eq!(stack.innermost_holder("B"), Some(0));
        assert!(stack.pop().is_some());
        assert!(stack.pop().is_none(), "the global table stays");
    }
}
