:- module(oro_sparql_xml,
          [ result_xml/2                % +Result, -XML
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(oro/sparql/oro_sparql_terms), [lexical_atom/2]).

/** <module> SPARQL Query Results XML Format

Writes the result of oro_sparql_eval (select(Vars, Rows) or ask(Bool))
as a document in the SPARQL Query Results XML Format (W3C
Recommendation, 2013): variables in projection order, one `result`
per row, a `binding` per bound variable, IRIs as `uri`, blank nodes
as `bnode`, literals with their `xml:lang` or `datatype`.
*/

%!  result_xml(+Result, -XML) is det.
%
%   XML is Result (select(Vars, Rows) or ask(Bool)) in the SPARQL Query
%   Results XML Format, a string.

result_xml(Result, XML) :-
    with_output_to(string(XML), write_result(Result)).

write_result(ask(Bool)) :-
    write_header,
    format('  <head/>~n  <boolean>~w</boolean>~n</sparql>~n', [Bool]).
write_result(select(Vars, Rows)) :-
    write_header,
    write('  <head>\n'),
    forall(member(V, Vars),
           ( write('    <variable name="'),
             xml_text(V),
             write('"/>\n')
           )),
    write('  </head>\n  <results>\n'),
    maplist(write_row, Rows),
    write('  </results>\n</sparql>\n').

write_header :-
    write('<?xml version="1.0"?>\n'),
    write('<sparql xmlns="http://www.w3.org/2005/sparql-results#">\n').

write_row(Row) :-
    write('    <result>\n'),
    maplist(write_binding, Row),
    write('    </result>\n').

write_binding(Name-Value) :-
    write('      <binding name="'),
    xml_text(Name),
    write('">'),
    write_term_xml(Value),
    write('</binding>\n').

write_term_xml(literal(L)) :-
    !,
    (   L = lang(Lang, Lex)
    ->  write('<literal xml:lang="'),
        xml_text(Lang),
        write('">')
    ;   L = type(Type, Lex)
    ->  write('<literal datatype="'),
        xml_text(Type),
        write('">')
    ;   Lex = L,
        write('<literal>')
    ),
    xml_text(Lex),
    write('</literal>').
write_term_xml(X) :-
    rdf_is_bnode(X),
    !,
    (   atom_concat('_:', Label, X)
    ->  true
    ;   Label = X
    ),
    write('<bnode>'),
    xml_text(Label),
    write('</bnode>').
write_term_xml(IRI) :-
    write('<uri>'),
    xml_text(IRI),
    write('</uri>').

xml_text(Text) :-
    lexical_atom(Text, Atom),
    atom_codes(Atom, Codes),
    maplist(xml_char, Codes).

xml_char(0'&) :- !, write('&amp;').
xml_char(0'<) :- !, write('&lt;').
xml_char(0'>) :- !, write('&gt;').
xml_char(0'") :- !, write('&quot;').
xml_char(0'\r) :- !, write('&#13;').
xml_char(C) :- put_char(C).
