:- module(oro_sparql_csv,
          [ result_csv/2                % +Result, -CSV
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(oro/sparql/oro_sparql_terms), [lexical_atom/2]).

/** <module> SPARQL 1.1 Query Results CSV Format

Writes the result of oro_sparql_eval as the SPARQL 1.1 Query Results
CSV Format (W3C Recommendation, 2013): a header of the variable names
(without `?`), one line per row ended by CRLF, IRIs bare, literals as
their lexical form only, blank nodes as `_:label`, unbound variables
empty; a field with a comma, a quote, CR or LF is quoted, its quotes
doubled.  The format has no booleans: an ASK result is written as the
one-column table `_askResult` holding `true` or `false`.
*/

%!  result_csv(+Result, -CSV) is det.
%
%   CSV is Result (select(Vars, Rows) or ask(Bool)) in the SPARQL 1.1
%   Query Results CSV Format, a string.

result_csv(ask(Bool), CSV) :-
    format(string(CSV), '_askResult\r\n~w\r\n', [Bool]).
result_csv(select(Vars, Rows), CSV) :-
    with_output_to(string(CSV),
                   ( write_fields(Vars),
                     forall(member(Row, Rows),
                            ( maplist(row_field(Row), Vars, Fields),
                              write_fields(Fields)
                            ))
                   )).

row_field(Row, Var, Field) :-
    (   memberchk(Var-Value, Row)
    ->  term_field(Value, Field)
    ;   Field = ''
    ).

term_field(literal(L), Lex) :-
    !,
    (   L = lang(_, Lex0)
    ->  true
    ;   L = type(_, Lex0)
    ->  true
    ;   Lex0 = L
    ),
    lexical_atom(Lex0, Lex).
term_field(X, Field) :-
    rdf_is_bnode(X),
    !,
    (   sub_atom(X, 0, 2, _, '_:')
    ->  Field = X
    ;   atom_concat('_:', X, Field)
    ).
term_field(IRI, IRI).

write_fields([]) :-
    write('\r\n').
write_fields([F|Fs]) :-
    write_field(F),
    forall(member(X, Fs),
           ( write(','),
             write_field(X)
           )),
    write('\r\n').

write_field(F) :-
    (   sub_atom(F, _, 1, _, C),
        memberchk(C, [',', '"', '\r', '\n'])
    ->  atomic_list_concat(Parts, '"', F),
        atomic_list_concat(Parts, '""', Escaped),
        format('"~w"', [Escaped])
    ;   write(F)
    ).
