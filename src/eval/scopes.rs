//! The stack of symbol tables, kept as one binding stack per name ("shallow binding").
//!
//! In: pushes and pops of tables (global, include file, macro call, function call) and
//! insertions and removals of names. Out: the innermost table holding a name and its value,
//! with one hash lookup however deep macro recursion goes. Holds: `bindings[name]` lists
//! exactly the (table, value) pairs of the tables that contain `name`, by ascending table;
//! `tables[i]` lists the names table `i` holds, so popping it is quick.

use super::value::Value;
use crate::hash::FastHash;
use std::collections::HashMap;
use std::rc::Rc;

/// Symbol tables, outermost (global) first.
pub(crate) struct ScopeStack {
    /// The names each table holds.
    tables: Vec<Vec<Rc<str>>>,
    /// For each name, its values with the table holding each, by ascending table index. A
    /// name whose tables are all gone keeps its (empty) list for the next call to reuse.
    bindings: HashMap<Rc<str>, Vec<(usize, Value)>, FastHash>,
}

impl ScopeStack {
    /// A stack holding only an empty global table.
    pub(crate) fn new() -> ScopeStack {
        ScopeStack {
            tables: vec![Vec::new()],
            bindings: HashMap::default(),
        }
    }

    /// Number of tables.
    pub(crate) fn len(&self) -> usize {
        self.tables.len()
    }

    /// Pushes a table of names and values (its names become visible, shadowing outer ones);
    /// a name given twice keeps its last value.
    pub(crate) fn push(&mut self, table: impl IntoIterator<Item = (Rc<str>, Value)>) {
        let index = self.tables.len();
        let mut names = Vec::new();
        for (name, value) in table {
            // Every other table is below `index`, so the binding goes last.
            match self.bindings.get_mut(&name) {
                Some(stack) if stack.last().is_some_and(|(i, _)| *i == index) => {
                    if let Some(last) = stack.last_mut() {
                        last.1 = value;
                    }
                    continue;
                }
                Some(stack) => stack.push((index, value)),
                None => {
                    self.bindings.insert(name.clone(), vec![(index, value)]);
                }
            }
            names.push(name);
        }
        self.tables.push(names);
    }

    /// Pops the innermost table; the global table is never popped.
    pub(crate) fn pop(&mut self) {
        if self.tables.len() <= 1 {
            return;
        }
        let index = self.tables.len() - 1;
        for name in self.tables.pop().unwrap_or_default() {
            if let Some(stack) = self.bindings.get_mut(&name) {
                if stack.last().is_some_and(|(i, _)| *i == index) {
                    stack.pop();
                }
            }
        }
    }

    /// Where table `index`'s binding of `name` is (`Ok`) or would go (`Err`) in `stack`.
    fn position(stack: &[(usize, Value)], index: usize) -> Result<usize, usize> {
        stack.binary_search_by_key(&index, |(i, _)| *i)
    }

    /// Stores `value` under `name` in table `index`.
    pub(crate) fn insert(&mut self, index: usize, name: Rc<str>, value: Value) {
        let Some(names) = self.tables.get_mut(index) else {
            return;
        };
        let stack = match self.bindings.get_mut(&name) {
            Some(stack) => stack,
            None => self.bindings.entry(name.clone()).or_default(),
        };
        match Self::position(stack, index) {
            Ok(at) => stack[at].1 = value,
            Err(at) => {
                stack.insert(at, (index, value));
                names.push(name);
            }
        }
    }

    /// Removes `name` from table `index`, returning its value.
    pub(crate) fn remove(&mut self, index: usize, name: &str) -> Option<Value> {
        let stack = self.bindings.get_mut(name)?;
        let at = Self::position(stack, index).ok()?;
        let (_, value) = stack.remove(at);
        if let Some(names) = self.tables.get_mut(index) {
            names.retain(|n| &**n != name);
        }
        Some(value)
    }

    /// The innermost table at or below `top` holding `name`, with the value there.
    pub(crate) fn binding_at_or_below(&self, name: &str, top: usize) -> Option<(usize, &Value)> {
        let stack = self.bindings.get(name)?;
        let at = stack.partition_point(|(i, _)| *i <= top);
        at.checked_sub(1).map(|at| (stack[at].0, &stack[at].1))
    }

    /// The innermost table holding `name`, with the value there.
    pub(crate) fn innermost_binding(&self, name: &str) -> Option<(usize, &Value)> {
        self.bindings
            .get(name)?
            .last()
            .map(|(index, value)| (*index, value))
    }

    /// The innermost table holding `name`.
    pub(crate) fn innermost_holder(&self, name: &str) -> Option<usize> {
        self.innermost_binding(name).map(|(index, _)| index)
    }

    /// The value of `name` in table `index`.
    pub(crate) fn get(&self, index: usize, name: &str) -> Option<&Value> {
        let stack = self.bindings.get(name)?;
        Self::position(stack, index).ok().map(|at| &stack[at].1)
    }

    /// The value of `name` in table `index`, to change in place.
    pub(crate) fn get_mut(&mut self, index: usize, name: &str) -> Option<&mut Value> {
        let stack = self.bindings.get_mut(name)?;
        Self::position(stack, index).ok().map(|at| &mut stack[at].1)
    }

    /// Every name in every table (for suggestions).
    pub(crate) fn names(&self) -> impl Iterator<Item = &str> {
        self.bindings
            .iter()
            .filter(|(_, stack)| !stack.is_empty())
            .map(|(name, _)| &**name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::Scope;

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
        assert_eq!(stack.binding_at_or_below("A", 0).map(|b| b.0), Some(0));
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
        assert_eq!(stack.binding_at_or_below("B", 0).map(|b| b.0), Some(0));
        assert!(stack.remove(1, "B").is_some());
        assert_eq!(stack.innermost_holder("B"), Some(0));
        stack.pop();
        assert_eq!(stack.len(), 1);
        stack.pop();
        assert_eq!(stack.len(), 1, "the global table stays");
        assert_eq!(stack.innermost_holder("B"), Some(0));
    }
}
