:- module(oro_sparql_tsv,
          [ result_tsv/2                % +Result, -TSV
          ]).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(oro/sparql/results/oro_sparql_ntriples), [write_rdf_term/1]).

/** <module> SPARQL 1.1 Query Results TSV Format

Writes the result of oro_sparql_eval as the SPARQL 1.1 Query Results
TSV Format (W3C Recommendation, 2013): a header of the variables
(with `?`), one line per row ended by LF, each term in Turtle syntax
as N-Triples writes it (`<IRI>`, `_:label`, `"text"@lang`,
`"lex"^^<datatype>`: write_rdf_term/1), unbound
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
    ->  with_output_to(string(Field), write_rdf_term(Value))
    ;   Field = ''
    ).

write_fields([]) :-
    nl.
write_fields([F|Fs]) :-
    write(F),
    forall(member(X, Fs),
           ( write('\t'),
             write(X)
           )),
    nl.
