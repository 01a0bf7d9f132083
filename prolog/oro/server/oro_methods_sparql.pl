:- module(oro_methods_sparql, []).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(oro/sparql/oro_sparql)).
:- use_module(library(oro/oro_names)).

/** <module> ORO methods: SPARQL

The protocol face of oro_sparql (ORO-SPEC §6.3, §13.3), declared as
clauses of the method table oro_methods:method/4, all on the robot's
model (`myself`):

  | method                        | answer                                   |
  |-------------------------------|------------------------------------------|
  | query(String key, String q)   | `["baboon","gorilla"]`: the distinct values of `?key` |
  | find(String var, Set p, Set f)| `["baboon"]`: find with SPARQL filters    |
  | sparql(String q)              | SPARQL 1.1 JSON results, raw (unquoted)  |

query and find answer values as ORO does: resources contracted
(`baboon`, `owl:Thing`), literals as their bare lexical form, blank
nodes and unbound rows left out.  A malformed query is the library's
`syntax_error(oro_sparql(Message, Position))`, a query running past
the `oro_query:time_limit` setting its
`resource_error(oro_query_time_limit(Seconds))`; oro_errors names them.
*/

:- multifile
    oro_methods:method/4.

oro_methods:method(query(string, string), querying,
                   "Runs a SPARQL SELECT query and returns the distinct values bound to the given variable.",
                   oro_methods_sparql:m_query).
oro_methods:method(find(string, set, set), querying,
                   "Returns the values of a variable that satisfy all the patterns and all the SPARQL filters.",
                   oro_methods_sparql:m_find).
oro_methods:method(sparql(string), querying,
                   "Runs a SPARQL SELECT or ASK query and returns the full results as SPARQL 1.1 JSON.",
                   oro_methods_sparql:m_sparql).

m_query(Key, Query, list(Texts)) :-
    oro_query_values(myself, Key, Query, Values),
    values_texts(Values, Texts).

m_find(Var, Patterns, Filters, list(Texts)) :-
    oro_find(myself, Var, Patterns, Filters, Values),
    values_texts(Values, Texts).

m_sparql(Query, raw(JSON)) :-
    oro_sparql_json(myself, Query, JSON).

%   values_texts(+Values, -Texts): the distinct texts of Values, as
%   string(Text) reply values.

values_texts(Values, Texts) :-
    maplist(oro_term_text, Values, Texts0),
    sort(Texts0, Texts1),
    maplist(string_value, Texts1, Texts).

string_value(Text, string(String)) :-
    atom_string(Text, String).
