:- module(w3c_sparql_known, [w3c_known_failure/3]).

/** <module> The W3C SPARQL tests that fail today, and why

w3c_known_failure(Category, Name, Reason): the test Name of Category
(folder of ../shared/w3c-sparql) fails through the endpoint, for
Reason.  test_w3c_sparql fails when a test outside this list fails, or
when a listed one passes: keep it, and the README's table, in step.
*/


w3c_known_failure('sparql10/distinct', 'All: Distinct', "not analysed yet (probably rdf_db reading numeric literals by value)").
w3c_known_failure('sparql10/distinct', 'Numbers: Distinct', "as All: Distinct").
w3c_known_failure('sparql10/expr-builtin', 'sameTerm-eq', "not analysed yet (probably rdf_db reading numeric literals by value)").
w3c_known_failure('sparql10/expr-builtin', 'sameTerm-not-eq', "not analysed yet (probably rdf_db reading numeric literals by value)").
w3c_known_failure('sparql10/expr-builtin', 'sameTerm-simple', "not analysed yet (probably rdf_db reading numeric literals by value)").
w3c_known_failure('sparql10/expr-builtin', 'str-1', "not analysed yet (probably rdf_db reading numeric literals by value)").
w3c_known_failure('sparql10/expr-builtin', 'str-2', "not analysed yet (probably rdf_db reading numeric literals by value)").
w3c_known_failure('sparql10/expr-equals', 'Equality 1-1 -- graph', "a numeric constant in a pattern matches by value in rdf_db (\"01\"^^xsd:integer matches 1), not as an RDF term").
w3c_known_failure('sparql10/expr-equals', 'Equality 1-2 -- graph', "as Equality 1-1 -- graph").
w3c_known_failure('sparql11/property-path', 'ZeroOrX property paths should only return terms in the graph and not also terms defined in the query', "not analysed yet: zero-length path with a constant end not in the graph").
