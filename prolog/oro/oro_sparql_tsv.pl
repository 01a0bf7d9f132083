:- module(oro_sparql_tsv,
          [ result_tsv/2                % +Result, -TSV
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(oro_sparql_functions, [lexical_atom/2]).

/** <module> SPARQL 1.1 Query Results TSV Format

Writes the result of oro_sparql_eval as the SPARQL 1.1 Query Results
TSV Format (W3C Recommendation, 2013): a header of the variables
(with `?`), one line per row ended by LF, each term in Turtle syntax
(`<IRI>`, `_:label`, `"text"@lang`, `"lex"^^<datatype>`), unbound
variables empty.  The format has no booleans: an ASK result is written
as the one-column table `?_askResult` holding `true` or `false`.
*/

%!  result_tsv(+Result, -TSV) is det.
%
%   TSV is Result (select(Vars, Rows) or ask(Bool)) in the SPARQL 1.1
%   Query Results TSV Format, a string.

result_tsv(ask(Bool), TSV) :-
    format(string(TSV), '?_askResult\n~w\n', [Bool]).
result_tsv(select(Vars, Rows), TSV) :-
    with_output_to(string(TSV),
                   ( maplist(var_header, Vars, Header),
                     write_fields(Header),
                     forall(member(Row, Rows),
                            ( maplist(row_field(Row), Vars, Fields),
                              write_fields(Fields)
                            ))
                   )).

var_header(Var, Header) :-
    atom_concat(?, Var, Header).

row_field(Row, Var, Field) :-
    (   memberchk(Var-Value, Row)
    ->  with_output_to(string(Field), write_term_tsv(Value))
    ;   Field = ''
    ).

write_term_tsv(literal(L)) :-
    !,
    (   L = lang(Lang, Lex)
    ->  write_string(Lex),
        format('@~w', [Lang])
    ;   L = type(Type, Lex)
    ->  write_string(Lex),
        format('^^<~w>', [Type])
    ;   write_string(L)
    ).
write_term_tsv(X) :-
    rdf_is_bnode(X),
    !,
    (   sub_atom(X, 0, 2, _, '_:')
    ->  write(X)
    ;   format('_:~w', [X])
    ).
write_term_tsv(IRI) :-
    format('<~w>', [IRI]).

write_string(Lex) :-
    lexical_atom(Lex, Atom),
    atom_codes(Atom, Codes),
    put_char('"'),
    maplist(string_char, Codes),
    put_char('"').

string_char(0'") :- !, write('\\"').
string_char(0'\\) :- !, write('\\\\').
string_char(0'\n) :- !, write('\\n').
string_char(0'\r) :- !, write('\\r').
string_char(0'\t) :- !, write('\\t').
string_char(C) :- put_char(C).

write_fields([]) :-
    nl.
write_fields([F|Fs]) :-
    write(F),
    forall(member(X, Fs),
           ( write('\t'),
             write(X)
           )),
    nl.
