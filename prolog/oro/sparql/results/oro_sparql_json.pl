:- module(oro_sparql_json,
          [ result_json/2               % +Result, -JSON
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(oro/sparql/oro_sparql_terms), [lexical_atom/2]).

/** <module> SPARQL 1.1 Query Results JSON Format

Writes the result of oro_sparql_eval as a document in the SPARQL 1.1
Query Results JSON Format.
*/

		 /*******************************
		 *         JSON RESULTS         *
		 *******************************/

%!  result_json(+Result, -JSON) is det.
%
%   JSON is Result (select(Vars, Rows) or ask(Bool)) in the SPARQL 1.1
%   Query Results JSON Format, a string on one line.

result_json(ask(Bool), JSON) :-
    format(string(JSON), '{"head":{},"boolean":~w}', [Bool]).
result_json(select(Vars, Rows), JSON) :-
    with_output_to(string(JSON),
                   ( write('{"head":{"vars":['),
                     write_separated(Vars, json_string),
                     write(']},"results":{"bindings":['),
                     write_separated(Rows, json_row),
                     write(']}}')
                   )).

write_separated([], _).
write_separated([H|T], Writer) :-
    call(Writer, H),
    forall(member(X, T),
           ( write(','),
             call(Writer, X)
           )).

json_row(Row) :-
    write('{'),
    write_separated(Row, json_binding),
    write('}').

json_binding(Name-Value) :-
    json_string(Name),
    write(':'),
    json_term(Value).

json_term(literal(L)) :-
    !,
    write('{"type":"literal","value":'),
    (   L = lang(Lang, Lex)
    ->  json_string(Lex),
        write(',"xml:lang":'),
        json_string(Lang)
    ;   L = type(T, Lex)
    ->  json_string(Lex),
        write(',"datatype":'),
        json_string(T)
    ;   json_string(L)
    ),
    write('}').
json_term(X) :-
    rdf_is_bnode(X),
    !,
    (   atom_concat('_:', Label, X)
    ->  true
    ;   Label = X
    ),
    write('{"type":"bnode","value":'),
    json_string(Label),
    write('}').
json_term(IRI) :-
    write('{"type":"uri","value":'),
    json_string(IRI),
    write('}').

json_string(Text) :-
    lexical_atom(Text, Atom),
    atom_codes(Atom, Codes),
    put_char('"'),
    maplist(json_char, Codes),
    put_char('"').

json_char(0'") :- !, write('\\"').
json_char(0'\\) :- !, write('\\\\').
json_char(0'\n) :- !, write('\\n').
json_char(0'\r) :- !, write('\\r').
json_char(0'\t) :- !, write('\\t').
json_char(C) :- C < 0x20, !, format('\\u~|~`0t~16r~4+', [C]).
json_char(C) :- put_char(C).
