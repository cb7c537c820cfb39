//! The collision record's CSV and table (`rime collision --format csv|table`), beside its JSON
//! ([`CollisionRecord`]'s serde form): one list of the record's quantities with their units, so
//! that the three formats cannot drift apart. The command line only prints them.

use super::records::{CollisionRecord, cell};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec;
use alloc::vec::Vec;

/// The time series' columns: the JSON arrays `t`, `xi`, `xi_dot`, `force` with their units.
pub const SERIES_HEADER: [&str; 4] = ["t [s]", "xi [m]", "xi_dot [m/s]", "force [N]"];

/// A quantity's value: a number, or a name (the status, the stick class).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A number in SI (empty in the CSV where it is not finite).
    Number(f64),
    /// A name.
    Text(&'static str),
}

/// One quantity of the record after the series: where it sits in the JSON record (`group.name`:
/// `ledger.closure`, `phase.contact`, `tangential.eps_t`; no group at the top), its value and
/// its SI unit (`1` for a ratio, empty for a name or ε).
#[derive(Debug, Clone, PartialEq)]
pub struct Quantity {
    /// `phase`, `ledger`, `tangential`, or `None` at the top of the record.
    pub group: Option<&'static str>,
    /// The field's name (a phase's name for `phase`).
    pub name: &'static str,
    /// Its value.
    pub value: Cell,
    /// Its SI unit.
    pub unit: &'static str,
}

impl Quantity {
    fn new(
        group: Option<&'static str>,
        name: &'static str,
        value: Cell,
        unit: &'static str,
    ) -> Self {
        Quantity {
            group,
            name,
            value,
            unit,
        }
    }

    /// The CSV's key: `group.name`, or the name at the top.
    pub fn key(&self) -> String {
        match self.group {
            Some(g) => format!("{g}.{}", self.name),
            None => self.name.to_string(),
        }
    }

    /// The value as a record prints it: every digit ([`cell`]), or the name.
    pub fn text(&self) -> String {
        match self.value {
            Cell::Number(v) => cell(v),
            Cell::Text(t) => t.to_string(),
        }
    }
}

impl CollisionRecord<'_> {
    /// The record's quantities after the series, in the order the CSV and the table give them:
    /// status, ε_N, t_c, ξ_max, the phases, the ledger, and an oblique impact's tangential side.
    pub fn quantities(&self) -> Vec<Quantity> {
        use Cell::{Number, Text};
        let mut q = vec![
            Quantity::new(None, "status", Text(self.status), ""),
            Quantity::new(None, "eps_n", Number(self.eps_n), "1"),
            Quantity::new(None, "t_c", Number(self.t_c.unwrap_or(f64::NAN)), "s"),
            Quantity::new(None, "xi_max", Number(self.xi_max), "m"),
        ];
        q.extend(
            self.phases
                .iter()
                .map(|p| Quantity::new(Some("phase"), p.name, Number(p.t), "s")),
        );
        let l = &self.ledger;
        let ledger = Some("ledger");
        q.extend([
            Quantity::new(ledger, "kinetic_in", Number(l.kinetic_in), "J"),
            Quantity::new(ledger, "kinetic_out", Number(l.kinetic_out), "J"),
            Quantity::new(ledger, "dissipated_bulk", Number(l.dissipated_bulk), "J"),
            Quantity::new(ledger, "dissipated_layer", Number(l.dissipated_layer), "J"),
            Quantity::new(ledger, "elastic_retained", Number(l.elastic_retained), "J"),
            Quantity::new(ledger, "adhesion", Number(l.adhesion), "J"),
            Quantity::new(ledger, "closure", Number(l.closure), "1"),
        ]);
        if let Some(o) = &self.tangential {
            let t = Some("tangential");
            // Units as docs/cli.md gives them (issue 37: the table's tangential rows had none).
            q.extend([
                Quantity::new(t, "class", Text(o.class), ""),
                Quantity::new(t, "eps_t", Number(o.eps_t), ""),
                Quantity::new(t, "energy_before", Number(o.energy_before), "J"),
                Quantity::new(t, "energy_after", Number(o.energy_after), "J"),
                Quantity::new(t, "friction_work", Number(o.friction_work), "J"),
                Quantity::new(t, "spin_change_1", Number(o.spin_change[0]), "rad/s"),
                Quantity::new(t, "spin_change_2", Number(o.spin_change[1]), "rad/s"),
            ]);
        }
        q
    }

    /// The record as CSV: the series (one row per sample, [`SERIES_HEADER`]), then each quantity
    /// as a `# key,value,unit` comment line.
    pub fn csv(&self) -> String {
        let mut s = SERIES_HEADER.join(",");
        s.push('\n');
        let rows = self.t.len();
        for i in 0..rows {
            let at = |v: &[f64]| v.get(i).map_or(String::new(), |x| cell(*x));
            s.push_str(&format!(
                "{},{},{},{}\n",
                at(self.t),
                at(self.xi),
                at(self.xi_dot),
                at(self.force)
            ));
        }
        for q in self.quantities() {
            s.push_str(&format!("# {},{},{}\n", q.key(), q.text(), q.unit));
        }
        s
    }

    /// The record as a table's rows `[quantity, value, unit]` (every digit: a surface that shows
    /// them to people rounds them); a quantity is named without its group.
    pub fn table_rows(&self) -> Vec<Vec<String>> {
        self.quantities()
            .into_iter()
            .map(|q| {
                let unit = if q.unit == "1" { "" } else { q.unit };
                vec![q.name.to_string(), q.text(), unit.to_string()]
            })
            .collect()
    }
}

#[cfg(all(test, feature = "json"))]
mod tests {
    use super::*;
    use crate::{Accuracy, Contact, Preset};
    use serde_json::Value as Json;

    /// The value at `key` (`ledger.closure`) of the JSON record.
    fn at<'a>(record: &'a Json, key: &str) -> &'a Json {
        key.split('.').fold(record, |j, k| &j[k])
    }

    #[test]
    fn issue_36_the_csv_and_table_carry_the_json_records_fields() {
        let mut scene = Preset::IceSticky.scene();
        scene.set("friction", "on").unwrap();
        let contact = Contact::new(&scene).unwrap();
        let g = 2e-3;
        let tr = contact.collision(g, 12, Accuracy::Precise).unwrap();
        let (r1, r2) = (scene.grains.radius_1, scene.grains.radius_2);
        let ob = contact.oblique(r1, r2, g, 1e-3, Accuracy::Precise).unwrap();
        let record = CollisionRecord::new(g, &tr, Some(&ob));
        let json = serde_json::to_value(&record).unwrap();
        let csv = record.csv();
        let mut lines = csv.lines();
        // The header names the JSON arrays, with their units.
        assert_eq!(lines.next(), Some("t [s],xi [m],xi_dot [m/s],force [N]"));
        let names: Vec<&str> = SERIES_HEADER
            .iter()
            .map(|h| h.split(' ').next().unwrap())
            .collect();
        // Each row is the arrays' sample, every digit (read back to the same double).
        let rows: Vec<&str> = lines.clone().take_while(|l| !l.starts_with('#')).collect();
        assert_eq!(rows.len(), json["t"].as_array().unwrap().len());
        for (i, row) in rows.iter().enumerate() {
            for (name, text) in names.iter().zip(row.split(',')) {
                let v: f64 = text.parse().unwrap();
                assert_eq!(Some(v), json[*name][i].as_f64(), "{name}[{i}]");
            }
        }
        // Each `# key,value,unit` line is the JSON record's field at that key.
        let mut seen = 0;
        for line in lines.filter(|l| l.starts_with("# ")) {
            let mut f = line[2..].split(',');
            let (key, value) = (f.next().unwrap(), f.next().unwrap());
            let j = if let Some(phase) = key.strip_prefix("phase.") {
                let p = json["phases"].as_array().unwrap();
                &p.iter().find(|p| p["name"] == phase).unwrap()["t"]
            } else if let Some(k) = key.strip_prefix("tangential.spin_change_") {
                let k: usize = k.parse().unwrap();
                &json["tangential"]["spin_change"][k - 1]
            } else {
                at(&json, key)
            };
            match j {
                Json::String(s) => assert_eq!(value, s, "{key}"),
                j => assert_eq!(value.parse::<f64>().ok(), j.as_f64(), "{key}"),
            }
            seen += 1;
        }
        // status, ε_N, t_c, ξ_max, the phases, 7 ledger lines, 7 tangential ones.
        assert_eq!(seen, 4 + json["phases"].as_array().unwrap().len() + 7 + 7);
        // The table: the same quantities, named without their group.
        let table = record.table_rows();
        assert_eq!(table.len(), seen);
        assert_eq!(table[1], ["eps_n", &cell(tr.eps_n), ""]);
        assert!(table.iter().any(|r| r[0] == "closure" && r[2].is_empty()));
        assert!(
            table
                .iter()
                .any(|r| r[0] == "spin_change_2" && r[2] == "rad/s")
        );
    }
}
