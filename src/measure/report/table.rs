//! The report's one table writer. Every section of the report builds its results as
//! [`Table`]s, each row's cells given once with both their texts, and `run` writes them all:
//! the Markdown into `report.md` (and the terminal), the CSV into the table's own file. The
//! two forms come from the same cells, so they cannot disagree.

use std::fmt::Display;

/// A column: its name in the Markdown table and in the CSV, either of which may be absent.
pub struct Column {
    markdown: Option<String>,
    csv: Option<&'static str>,
    /// Repeated in the Markdown once per value of the table's [`Table::across`] column.
    each: bool,
}

impl Column {
    /// Builds a column in both forms.
    pub fn new(markdown: &str, csv: &'static str) -> Self {
        Self {
            markdown: Some(markdown.to_owned()),
            csv: Some(csv),
            each: false,
        }
    }

    /// Builds a column in the Markdown only.
    pub fn markdown(name: &str) -> Self {
        Self {
            markdown: Some(name.to_owned()),
            csv: None,
            each: false,
        }
    }

    /// Builds a column in the CSV only.
    pub fn csv(name: &'static str) -> Self {
        Self {
            markdown: None,
            csv: Some(name),
            each: false,
        }
    }

    /// Shows the column in the Markdown once per value of the table's `across` column.
    ///
    /// Its name there has `{}` standing for that value.
    pub fn each(self) -> Self {
        Self { each: true, ..self }
    }
}

/// One cell: its Markdown text and its CSV text (written as given: see [`quoted`]).
///
/// A column absent from one form ignores that text.
pub struct Cell {
    markdown: String,
    csv: String,
}

impl Cell {
    pub fn new(markdown: impl Into<String>, csv: impl Into<String>) -> Self {
        Self {
            markdown: markdown.into(),
            csv: csv.into(),
        }
    }

    /// Builds a cell with the same text in both forms.
    pub fn same(value: impl Display) -> Self {
        let text = value.to_string();
        Self::new(text.clone(), text)
    }

    /// Builds a cell for a column in the Markdown only.
    pub fn markdown(text: impl Into<String>) -> Self {
        Self::new(text, "")
    }

    /// Builds a cell for a column in the CSV only.
    pub fn csv(value: impl Display) -> Self {
        Self::new("", value.to_string())
    }

    /// Builds a cell for a column in the CSV only: empty when absent.
    pub fn csv_option(value: Option<impl Display>) -> Self {
        Self::new("", or_empty(value))
    }
}

/// Formats an optional CSV field: empty when absent.
pub fn or_empty(value: Option<impl Display>) -> String {
    value.map_or(String::new(), |v| v.to_string())
}

/// Quotes a CSV field that may hold commas.
pub fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('"', "\"\""))
}

/// Formats the Markdown cell of a run that diverged at `step`.
pub fn diverged(step: u64) -> String {
    format!("diverged @{step}")
}

/// One table of the report: a heading, the columns, the rows, and the CSV file it is written to.
///
/// There is no file for a table shown only in the Markdown.
pub struct Table {
    heading: String,
    file: Option<&'static str>,
    columns: Vec<Column>,
    across: Option<usize>,
    rows: Vec<Vec<Cell>>,
    note: String,
}

impl Table {
    pub fn new(
        heading: impl Into<String>,
        file: Option<&'static str>,
        columns: Vec<Column>,
    ) -> Self {
        Self {
            heading: heading.into(),
            file,
            columns,
            across: None,
            rows: Vec::new(),
            note: String::new(),
        }
    }

    /// Spreads the Markdown across this column: a wide Markdown table over a long CSV.
    ///
    /// Consecutive rows that differ only in this column (a CSV-only one) and in the `each`
    /// columns share one Markdown line, which shows their `each` cells side by side, a set per
    /// value of this column (its cells' Markdown text). The CSV keeps a line per row.
    pub fn across(self, column: usize) -> Self {
        Self {
            across: Some(column),
            ..self
        }
    }

    /// Adds a row: a cell per column, in the columns' order.
    pub fn row(&mut self, cells: Vec<Cell>) {
        assert_eq!(cells.len(), self.columns.len(), "{}", self.heading);
        self.rows.push(cells);
    }

    /// Adds a line of prose under the table, in the Markdown only (the side-by-side's).
    #[cfg_attr(not(feature = "peers"), allow(dead_code))]
    pub fn note(&mut self, line: impl Display) {
        self.note += &format!("{line}\n");
    }

    /// Returns the CSV file to write, if any.
    pub fn file(&self) -> Option<&'static str> {
        self.file
    }

    /// Builds the CSV: the header, then a line per row.
    pub fn csv(&self) -> String {
        let columns: Vec<usize> = (0..self.columns.len())
            .filter(|&c| self.columns[c].csv.is_some())
            .collect();
        let mut text = csv_line(
            columns
                .iter()
                .map(|&c| self.columns[c].csv.unwrap_or_default()),
        );
        for row in &self.rows {
            text += &csv_line(columns.iter().map(|&c| row[c].csv.as_str()));
        }
        text
    }

    /// Returns a row's value of the `across` column, as the Markdown shows it.
    fn value_of<'a>(&self, row: &'a [Cell]) -> &'a str {
        self.across.map_or("", |a| row[a].markdown.as_str())
    }

    /// Builds the Markdown: the heading, the table, and the notes after a blank line.
    pub fn markdown(&self) -> String {
        let mut values: Vec<&str> = Vec::new();
        for row in &self.rows {
            if !values.contains(&self.value_of(row)) {
                values.push(self.value_of(row));
            }
        }
        // The Markdown's columns, each a name and what fills it: a column's cell, or an
        // `each` column's cell in the row with one value of `across`. The `each` columns
        // expand where the first of them stands.
        let each: Vec<usize> = (0..self.columns.len())
            .filter(|&c| self.columns[c].each && self.columns[c].markdown.is_some())
            .collect();
        let mut slots: Vec<(String, usize, Option<&str>)> = Vec::new();
        for (c, column) in self.columns.iter().enumerate() {
            match &column.markdown {
                Some(name) if !column.each => slots.push((name.clone(), c, None)),
                Some(_) if each.first() == Some(&c) => {
                    for &value in &values {
                        for &e in &each {
                            let name = self.columns[e].markdown.as_deref().unwrap_or_default();
                            slots.push((name.replace("{}", value), e, Some(value)));
                        }
                    }
                }
                _ => {}
            }
        }
        let keys: Vec<usize> = slots
            .iter()
            .filter(|s| s.2.is_none())
            .map(|s| s.1)
            .collect();
        let same_line = |a: &[Cell], b: &[Cell]| {
            self.across.is_some() && keys.iter().all(|&k| a[k].markdown == b[k].markdown)
        };

        let mut text = format!("## {}\n\n", self.heading);
        text += &cells_line(slots.iter().map(|s| s.0.as_str()));
        text += &format!("|{}\n", "---|".repeat(slots.len()));
        for group in self.rows.chunk_by(|a, b| same_line(a, b)) {
            text += &cells_line(slots.iter().map(|&(_, c, value)| {
                let row = match value {
                    None => group.first(),
                    Some(value) => group.iter().find(|r| self.value_of(r) == value),
                };
                row.map_or("", |r| r[c].markdown.as_str())
            }));
        }
        if !self.note.is_empty() {
            text += "\n";
            text += &self.note;
        }
        text
    }
}

/// Joins `fields` with commas and ends the line with a newline.
fn csv_line<'a>(fields: impl Iterator<Item = &'a str>) -> String {
    fields.collect::<Vec<_>>().join(",") + "\n"
}

/// Formats `cells` as a Markdown line, `| a | b |`, an empty cell as `| |`.
fn cells_line<'a>(cells: impl Iterator<Item = &'a str>) -> String {
    let mut text = String::from("|");
    for cell in cells {
        if !cell.is_empty() {
            text += " ";
            text += cell;
        }
        text += " |";
    }
    text + "\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks two rows per line in the Markdown and one each in the CSV; an empty cell stays `| |`.
    #[test]
    fn a_wide_markdown_table_over_a_long_csv() {
        let mut table = Table::new(
            "Heading",
            Some("t.csv"),
            vec![
                Column::new("k", "k"),
                Column::csv("integrator"),
                Column::new("{} error", "error_px").each(),
                Column::markdown("note"),
            ],
        )
        .across(1);
        for (k, integrator, error) in [(1, "a", Some(0.5)), (1, "b", None), (2, "a", None)] {
            table.row(vec![
                Cell::same(k),
                Cell::same(integrator),
                Cell::new(
                    error.map_or("-".to_owned(), |e| format!("{e}")),
                    or_empty(error),
                ),
                Cell::markdown(""),
            ]);
        }
        assert_eq!(
            table.markdown(),
            "## Heading\n\n| k | a error | b error | note |\n|---|---|---|---|\n\
             | 1 | 0.5 | - | |\n| 2 | - | | |\n"
        );
        assert_eq!(table.csv(), "k,integrator,error_px\n1,a,0.5\n1,b,\n2,a,\n");
        assert_eq!(quoted("a \"b\", c"), "\"a \"\"b\"\", c\"");
        assert_eq!(diverged(7), "diverged @7");
    }
}
