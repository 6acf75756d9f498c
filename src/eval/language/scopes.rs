//! The stack of symbol tables, kept as one binding stack per name ("shallow binding").
//!
//! In: pushes and pops of tables (global, include file, macro call, function call) and
//! insertions and removals of names. Out: the innermost table holding a name and its value,
//! with one array lookup (names are interned [`Symbol`]s) however deep macro recursion goes. Holds: `bindings[name]` lists
//! exactly the (table, value) pairs of the tables that contain `name`, by ascending table;
//! `tables[i]` lists the names table `i` holds, so popping it is quick.

use super::value::Value;
use crate::syntax::symbol::Symbol;

/// Symbol tables, outermost (global) first.
pub(crate) struct ScopeStack {
    /// The names each table holds.
    tables: Vec<Vec<Symbol>>,
    /// For each name, by [`Symbol::index`], its values with the table holding each, by
    /// ascending table index. A name whose tables are all gone keeps its (empty) list for the
    /// next call to reuse.
    bindings: Vec<Vec<(usize, Value)>>,
    /// Every name that has had a binding, for suggestions.
    seen: Vec<Symbol>,
    /// Emptied name lists of popped tables, reused by the next pushes.
    spare: Vec<Vec<Symbol>>,
}

impl ScopeStack {
    /// A stack holding only an empty global table.
    pub(crate) fn new() -> ScopeStack {
        ScopeStack {
            tables: vec![Vec::new()],
            bindings: Vec::new(),
            seen: Vec::new(),
            spare: Vec::new(),
        }
    }

    /// Number of tables.
    pub(crate) fn len(&self) -> usize {
        self.tables.len()
    }

    /// The binding stack of `name`, created empty on first use.
    fn stack_mut(&mut self, name: Symbol) -> &mut Vec<(usize, Value)> {
        let slot = name.index();
        if slot >= self.bindings.len() {
            self.bindings.resize_with(slot + 1, Vec::new);
        }
        if self.bindings[slot].capacity() == 0 {
            self.seen.push(name);
        }
        &mut self.bindings[slot]
    }

    /// The binding stack of `name`, if it ever had one.
    fn stack(&self, name: Symbol) -> Option<&Vec<(usize, Value)>> {
        self.bindings.get(name.index())
    }

    /// Pushes a table of names and values (its names become visible, shadowing outer ones);
    /// a name given twice keeps its last value.
    pub(crate) fn push(&mut self, table: impl IntoIterator<Item = (Symbol, Value)>) {
        let index = self.tables.len();
        let mut names = self.spare.pop().unwrap_or_default();
        for (name, value) in table {
            // Every other table is below `index`, so the binding goes last.
            let stack = self.stack_mut(name);
            if let Some(last) = stack.last_mut().filter(|(i, _)| *i == index) {
                last.1 = value;
                continue;
            }
            stack.push((index, value));
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
        let mut names = self.tables.pop().unwrap_or_default();
        for name in names.drain(..) {
            if let Some(stack) = self.bindings.get_mut(name.index()) {
                if stack.last().is_some_and(|(i, _)| *i == index) {
                    stack.pop();
                }
            }
        }
        self.spare.push(names);
    }

    /// Where table `index`'s binding of `name` is (`Ok`) or would go (`Err`) in `stack`.
    fn position(stack: &[(usize, Value)], index: usize) -> Result<usize, usize> {
        stack.binary_search_by_key(&index, |(i, _)| *i)
    }

    /// Stores `value` under `name` in table `index`.
    pub(crate) fn insert(&mut self, index: usize, name: Symbol, value: Value) {
        if index >= self.tables.len() {
            return;
        }
        let stack = self.stack_mut(name);
        match Self::position(stack, index) {
            Ok(at) => stack[at].1 = value,
            Err(at) => {
                stack.insert(at, (index, value));
                self.tables[index].push(name);
            }
        }
    }

    /// Removes `name` from table `index`, returning its value.
    pub(crate) fn remove(&mut self, index: usize, name: Symbol) -> Option<Value> {
        let stack = self.bindings.get_mut(name.index())?;
        let at = Self::position(stack, index).ok()?;
        let (_, value) = stack.remove(at);
        if let Some(names) = self.tables.get_mut(index) {
            names.retain(|n| *n != name);
        }
        Some(value)
    }

    /// The innermost table at or below `top` holding `name`, with the value there.
    pub(crate) fn binding_at_or_below(&self, name: Symbol, top: usize) -> Option<(usize, &Value)> {
        let stack = self.stack(name)?;
        let at = stack.partition_point(|(i, _)| *i <= top);
        at.checked_sub(1).map(|at| (stack[at].0, &stack[at].1))
    }

    /// The innermost table holding `name`, with the value there.
    #[inline]
    pub(crate) fn innermost_binding(&self, name: Symbol) -> Option<(usize, &Value)> {
        self.stack(name)?
            .last()
            .map(|(index, value)| (*index, value))
    }

    /// The innermost table holding `name`.
    pub(crate) fn innermost_holder(&self, name: Symbol) -> Option<usize> {
        self.innermost_binding(name).map(|(index, _)| index)
    }

    /// The value of `name` in table `index`.
    pub(crate) fn get(&self, index: usize, name: Symbol) -> Option<&Value> {
        let stack = self.stack(name)?;
        Self::position(stack, index).ok().map(|at| &stack[at].1)
    }

    /// The value of `name` in table `index`, to change in place.
    pub(crate) fn get_mut(&mut self, index: usize, name: Symbol) -> Option<&mut Value> {
        let stack = self.bindings.get_mut(name.index())?;
        Self::position(stack, index).ok().map(|at| &mut stack[at].1)
    }

    /// Every name in every table (for suggestions).
    pub(crate) fn names(&self) -> impl Iterator<Item = &str> {
        self.seen
            .iter()
            .filter(|name| self.stack(**name).is_some_and(|stack| !stack.is_empty()))
            .map(|name| name.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::language::Scope;

    fn name(s: &str) -> Symbol {
        Symbol::intern(s)
    }

    #[test]
    fn inner_tables_shadow_outer_ones_until_popped() {
        let mut stack = ScopeStack::new();
        stack.insert(0, name("A"), Value::Float(1.0));
        let mut table = Scope::default();
        table.insert(name("A"), Value::Float(2.0));
        stack.push(table);
        assert_eq!(stack.innermost_holder(name("A")), Some(1));
        assert_eq!(
            stack.binding_at_or_below(name("A"), 0).map(|b| b.0),
            Some(0)
        );
        stack.pop();
        assert_eq!(stack.innermost_holder(name("A")), Some(0));
    }

    #[test]
    fn inserting_into_an_outer_table_keeps_the_index_ordered() {
        let mut stack = ScopeStack::new();
        stack.push(Scope::default());
        stack.insert(1, name("B"), Value::Float(1.0));
        stack.insert(0, name("B"), Value::Float(2.0));
        assert_eq!(stack.innermost_holder(name("B")), Some(1));
        assert_eq!(
            stack.binding_at_or_below(name("B"), 0).map(|b| b.0),
            Some(0)
        );
        assert!(stack.remove(1, name("B")).is_some());
        assert_eq!(stack.innermost_holder(name("B")), Some(0));
        stack.pop();
        assert_eq!(stack.len(), 1);
        stack.pop();
        assert_eq!(stack.len(), 1, "the global table stays");
        assert_eq!(stack.innermost_holder(name("B")), Some(0));
    }
}
