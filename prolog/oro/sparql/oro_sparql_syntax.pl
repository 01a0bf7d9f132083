:- module(oro_sparql_syntax,
          [ tok//1,                     % ?Token
            tokp//2,                    % ?Token, -Position
            kw//1,                      % ?Keyword
            peek_kw//1,                 % ?Keyword
            peek_punct//1,              % +Punct
            here//1,                    % -Position
            semantic_error/3,           % +Format, +Args, +Position
            no_aggregates/2             % +St0, -St
          ]).
:- use_module(library(lists)).

/** <module> The SPARQL grammar's primitives: tokens and errors

The nonterminals with which every part of the SPARQL grammar
(oro_sparql_grammar, oro_sparql_triples, oro_sparql_expressions) reads
the tokens of oro_sparql_lexer, t(Token, Position).  A token that does
not match is noted as expected at its position (in the global variable
`oro_sparql_far`, which parse_text/3 of oro_sparql_grammar sets for
each parse), so that a query that does not parse gets a syntax error
naming what was expected at the furthest position reached.
*/

		 /*******************************
		 *      PARSING: PRIMITIVES     *
		 *******************************/

%!  tok(?Token)// is semidet.
%!  tokp(?Token, -Position)// is semidet.
%
%   The next token is Token (at the 0-based character Position); when
%   it is not, Token is noted as expected there.

tok(T, [t(T0, P)|S], S) :-
    (   T0 = T
    ->  true
    ;   note_expected(P, T),
        fail
    ).

tokp(T, P, [t(T0, P)|S], S) :-
    (   T0 = T
    ->  true
    ;   note_expected(P, T),
        fail
    ).

%!  kw(?Keyword)// is semidet.
%!  peek_kw(?Keyword)// is semidet.
%
%   The next token is the keyword Keyword (lower case); peek_kw//1
%   does not read it.

kw(K) --> tok(word(K, _)).

peek_kw(K, S, S) :-
    S = [t(word(K, _), _)|_].

%   quiet_word(+Keyword, -Pos): the next token is Keyword (not noted
%   as expected: for keywords that are recognised only to be refused).

quiet_word(K, P, [t(word(K, _), P)|S], S).

%!  here(-Position)// is semidet.
%
%   Position is the position of the next token (not read).

here(P, S, S) :-
    S = [t(_, P)|_].

note_expected(P, T) :-
    nb_getval(oro_sparql_far, far(P0, Ts0)),
    (   P > P0
    ->  nb_setval(oro_sparql_far, far(P, [T]))
    ;   P =:= P0,
        \+ ( member(T0, Ts0), T0 =@= T )
    ->  nb_setval(oro_sparql_far, far(P, [T|Ts0]))
    ;   true
    ).

%!  semantic_error(+Format, +Args, +Position) is det.
%
%   Never returns: throw the error of a query that parses but breaks a rule of the
%   grammar (a variable bound twice, a blank node label reused...):
%   parse_text/3 of oro_sparql_grammar turns it into a syntax error
%   naming the line and column of Position.

semantic_error(Format, Args, P) :-
    throw(oro_sparql_error(Format, Args, P)).

%!  peek_punct(+Punct)// is semidet.
%
%   The next token is the punctuation Punct (not read); when it is
%   not, Punct is noted as expected there.

peek_punct(X, S, S) :-
    S = [t(T, P)|_],
    (   T == punct(X)
    ->  true
    ;   note_expected(P, punct(X)),
        fail
    ).

%!  no_aggregates(+St0, -St) is det.
%
%   St is the parser state St0 where aggregates are not allowed
%   (inside a group graph pattern, an EXISTS, a FILTER...).

no_aggregates(st(P, B, C, _), st(P, B, C, no_aggregates)).
