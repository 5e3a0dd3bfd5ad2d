//! Values between Python and Rust: TOML structures (a scenario as a dict) both ways, JSON
//! documents (summary.json, modes.json) to Python, vectors to numpy arrays.

use hawser::math::{Real, Vec3};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// A TOML value as a Python object: tables as dicts, arrays as lists.
pub fn toml_to_py<'py>(py: Python<'py>, v: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        toml::Value::String(s) => PyString::new(py, s).into_any(),
        toml::Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        toml::Value::Float(x) => PyFloat::new(py, *x).into_any(),
        toml::Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        toml::Value::Datetime(d) => PyString::new(py, &d.to_string()).into_any(),
        toml::Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| toml_to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        toml::Value::Table(t) => table_to_py(py, t)?.into_any(),
    })
}

/// A TOML table as a Python dict.
pub fn table_to_py<'py>(py: Python<'py>, t: &toml::Table) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (k, v) in t {
        d.set_item(k, toml_to_py(py, v)?)?;
    }
    Ok(d)
}

/// A Python value as TOML: dicts (string keys) as tables, lists and tuples (and numpy arrays)
/// as arrays, bool, int, float (numpy scalars too) and str as themselves. `key` names the
/// value in the error.
pub fn py_to_toml(obj: &Bound<'_, PyAny>, key: &str) -> PyResult<toml::Value> {
    if obj.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(obj.extract()?));
    }
    if obj.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(obj.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "`{key}`: the integer {obj} does not fit in 64 bits"
            ))
        })?));
    }
    if obj.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(obj.extract()?));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(toml::Value::String(s.to_cow()?.into_owned()));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        return Ok(toml::Value::Table(dict_to_table(d, key)?));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let mut items = Vec::new();
        for (i, x) in obj.try_iter()?.enumerate() {
            items.push(py_to_toml(&x?, &format!("{key}[{i}]"))?);
        }
        return Ok(toml::Value::Array(items));
    }
    // numpy arrays and scalars: their Python equivalents.
    if obj.hasattr("tolist")? {
        let plain = obj.call_method0("tolist")?;
        if !plain.is(obj) {
            return py_to_toml(&plain, key);
        }
    }
    Err(PyTypeError::new_err(format!(
        "`{key}`: a {} cannot be a scenario value (numbers, strings, booleans, lists and dicts \
         can)",
        obj.get_type().name()?
    )))
}

/// A dict with string keys as a TOML table; `key` is the dict's own key ("" at the top).
pub fn dict_to_table(d: &Bound<'_, PyDict>, key: &str) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let k: String = k.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "the keys of a scenario dict are strings; `{key}` has the key {k}"
            ))
        })?;
        let path = match key.is_empty() {
            true => k.clone(),
            false => format!("{key}.{k}"),
        };
        if v.is_none() {
            // None leaves a key out (TOML has no null).
            continue;
        }
        t.insert(k, py_to_toml(&v, &path)?);
    }
    Ok(t)
}

/// A JSON document as Python objects.
pub fn json_to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u)) => u.into_pyobject(py)?.into_any(),
            _ => PyFloat::new(py, n.as_f64().unwrap_or(f64::NAN)).into_any(),
        },
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| json_to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, json_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// A 1-D float array.
pub fn array1<'py>(py: Python<'py>, v: Vec<Real>) -> Bound<'py, PyAny> {
    PyArray1::from_vec(py, v).into_any()
}

/// An (n, 3) float array of vectors.
pub fn array_n3<'py>(py: Python<'py>, v: &[Vec3]) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<Real> = v.iter().flat_map(|x| [x.x, x.y, x.z]).collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([v.len(), 3])?
        .into_any())
}

/// A 3-vector as a float array of 3.
pub fn vec3<'py>(py: Python<'py>, v: Vec3) -> Bound<'py, PyAny> {
    PyArray1::from_slice(py, v.as_slice()).into_any()
}
